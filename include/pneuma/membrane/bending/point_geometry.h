#pragma once

/**
 * @file
 * The geometry of a point of a shell cell for the bending terms
 * (membrane/bending/kirchhoff_love.h): the parametric derivatives of the
 * cell's scalar shape functions at a unit point, the point derivatives g
 * of a position field from its nodal values, the reference frame of a
 * point, and the exact gradient and Hessian of a point energy by Sacado.
 *
 * Positions are interpolated from the cell's nodes with its own shape
 * functions: for degree 1 and 2 the membrane's MappingQ of the same degree
 * is that interpolant (its support points are the Gauss-Lobatto points,
 * the nodes of FE_Q for these degrees), so the reference X(xi) is the
 * mapping's.
 */

#include <deal.II/base/point.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <pneuma/membrane/bending/kirchhoff_love.h>
#include <pneuma/membrane/reference_geometry.h>

#include <array>
#include <vector>

namespace pneuma
{
  namespace membrane
  {
    namespace bending
    {
      using namespace dealii;

      /// N_,1 N_,2 N_,11 N_,12 N_,22 of each node's scalar shape function.
      struct ShapeDerivatives
      {
        unsigned int                                      n_nodes = 0;
        std::array<std::array<double, 5>, max_cell_nodes> d{};
      };

      /// The shape derivatives of the scalar element @p base at @p xi.
      ShapeDerivatives
      shape_derivatives(const FiniteElement<2, 3> &base, const Point<2> &xi);

      /// The reference positions of a cell's nodes (the mapping at the
      /// scalar element's support points); one per thread.
      class NodePositions
      {
      public:
        NodePositions(const Mapping<2, 3>       &mapping,
                      const FiniteElement<2, 3> &base);
        /// The nodes of @p cell (valid until the next call).
        const std::vector<Vec<double>> &
        of(const Triangulation<2, 3>::cell_iterator &cell);

      private:
        FEValues<2, 3>           values;
        std::vector<Vec<double>> x;
      };

      /// The point on face @p face of a cell with nodes @p x nearest to
      /// @p p (a point of that edge): its unit point.
      Point<2>
      locate_on_face(const FiniteElement<2, 3>      &base,
                     const std::vector<Vec<double>> &x,
                     const unsigned int              face,
                     const Vec<double>              &p);

      /// The point derivatives g (15) of the nodal positions @p x.
      void
      point_derivatives(const std::vector<Vec<double>> &x,
                        const ShapeDerivatives         &shape,
                        double                          g[15]);

      /// The position at @p xi of the nodal positions @p x.
      Vec<double>
      position(const FiniteElement<2, 3>      &base,
               const std::vector<Vec<double>> &x,
               const Point<2>                 &xi);

      /// A reference point: its unit normal N, frame (E_1, E_2), the area
      /// factor |X_,1 x X_,2| and the PointFrame of the energies.
      struct ReferencePoint
      {
        Vec<double> N, E1, E2;
        double      area = 0.;
        PointFrame  frame;
      };

      /**
       * The reference point of derivatives @p G (15) with the material
       * frame's first axis along the projection of @p warp (zero: along
       * X_,1), bending stiffness @p D (frame components) and normal sign
       * @p sign.
       */
      ReferencePoint
      reference_point(const double       G[15],
                      const Vec<double> &warp,
                      const double       D[2][2][2][2],
                      const double       sign);

      /// The unit point on face @p face of the unit square at parameter
      /// @p s in [0, 1], the face's parametric direction and its outward
      /// parametric direction.
      Point<2>
      face_point(const unsigned int face, const double s);
      std::array<double, 2>
      face_direction(const unsigned int face);
      std::array<double, 2>
      face_outward(const unsigned int face);

      /**
       * Add the weighted gradient and Hessian of a point energy in point
       * derivatives (15 per side, @p n_sides sides) to a local residual
       * and matrix (either may be null): side s's node a, component c is
       * the local dof index[s][a][c], and its g-slot k derivative is
       * shape[s].d[a][k].
       */
      void
      add_point_terms(const unsigned int                                n_sides,
                      const ShapeDerivatives                           *shape,
                      const std::array<std::array<unsigned int, 3>, 9> *index,
                      const double       *gradient,
                      const double       *hessian,
                      Vector<double>     *residual,
                      FullMatrix<double> *matrix);
    } // namespace bending
  }   // namespace membrane
} // namespace pneuma
