#pragma once

/**
 * @file
 * The cable elements (doc/theory.md §8): one variant per element, each one
 * .cc file in source/cables/elements/ with one registration line
 * (core/registry.h, doc/architecture.md "Add a cable element"). The input
 * chooses it with "Cables/Cable <k>/Element"; its constants live in the
 * subsection of its name, e.g. "Cables/Cable 1/solid beam/Law".
 *
 * The registered elements:
 * - "cable" (elements/cable.cc): the tension-only truss of Irvine's
 *   elastic cable, N = EA (lambda - 1) in tension and a slack ratio times
 *   that in compression (kernel TensionOnlyCable, doc/theory.md §8.1);
 * - "solid beam" (elements/solid_beam.cc): the source paper's solid-beam
 *   element after Konyukhov & Schweizerhof, the mid-line and the two
 *   semi-axis vectors of the elliptic section per node, 3D hyperelastic
 *   material over the section (kernels SolidBeamElement and
 *   SolidBeamSection, doc/theory.md §8.2).
 *
 * <h3>What an element is to the cable system</h3>
 * Every cable has its own mesh (Triangulation<1,3>, straight cells) and
 * FE_Q(1)^n with n = n_components() unknowns per node. Components 0-2 are
 * the displacement of the mid-line: the supports, the dead loads
 * (gravity, distributed load, end forces), the contact and the near-null
 * space act on them, and the cable system handles them for every element.
 * Further components (e.g. the section vectors of the solid beam) belong to
 * the element: it gives their reference values (reference_values()), and a
 * fixed end holds them.
 *
 * The element gives the internal virtual work of one cell: its residual
 * \f$r_i = \partial W/\partial u_i\f$ (W the strain energy of the cell,
 * per reference length integrated along S) and its consistent tangent
 * \f$\partial r_i/\partial u_j\f$, plus the cell values written to the VTU
 * (output_names()) and reported in the statistics (CableCellOutput).
 * Loads per unstressed length are divided by the length ratio
 * \f$\rho = L_{ref}/L_0\f$ by the cable system; an element with a
 * prestress applies rho to its own strain measure (setup()).
 *
 * <h3>Life of an element</h3>
 * One instance per cable: the Registry's default constructor,
 * declare_parameters() (binds the constants with add_parameter, in the
 * subsection of the element's name), parse_parameters() (checks them),
 * then, once the mesh is built, setup() with the cable's common entries
 * and rho; cell_terms() at every assembly; commit_end_moment() after each
 * converged step of a cable loaded by an end moment.
 */

#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <pneuma/core/registry.h>

#include <string>
#include <vector>

namespace pneuma
{
  namespace cables
  {
    using namespace dealii;

    struct CableDefinition;

    /// A node of the reference mesh, for the reference values of an
    /// element's own unknowns.
    struct CableNode
    {
      /// Reference position X.
      Point<3> position;
      /// Unit reference tangent: the mean of the adjacent cells' tangents.
      Tensor<1, 3> tangent;
      /// The shape's preferred direction of a section axis at X (outward
      /// radial for a ring or helix, not normalised), or zero if the shape
      /// has none (CableShape::section_direction()).
      Tensor<1, 3> section_direction;
    };

    /// What one cell reports besides its residual and tangent.
    struct CableCellOutput
    {
      /// The cell values of CableElement::output_names(), in that order.
      std::vector<double> values;
      /// Axial force N [N], positive in tension.
      double axial_force = 0.;
      /// Magnitude of the bending moment and of the torsion moment [N m]
      /// (zero for an element without moments).
      double bending_moment = 0., torsion_moment = 0.;
    };

    /// One kind of cable element.
    class CableElement
    {
    public:
      virtual ~CableElement() = default;

      /// Declare (and bind) the element's constants in the current
      /// subsection.
      virtual void
      declare_parameters(ParameterHandler &prm) = 0;
      /// Check the constants; messages name @p path.
      virtual void
      parse_parameters(ParameterHandler &prm, const std::string &path) = 0;

      /// Unknowns per node; components 0-2 are the mid-line displacement.
      virtual unsigned int
      n_components() const = 0;
      /// VTU names of the n_components() nodal fields; equal names of
      /// consecutive components form one vector ("displacement" x 3 first).
      virtual std::vector<std::string>
      component_names() const = 0;
      /// Names of the cell fields CableCellOutput::values.
      virtual std::vector<std::string>
      output_names() const = 0;
      /// The quadrature rule along a cell for the internal forces (e.g. one
      /// Gauss point: exact for a constant strain, reduced integration
      /// against shear locking).
      virtual Quadrature<1>
      quadrature() const = 0;

      /// The components that are the changes of the section semi-axis
      /// vectors a1 (the first three) and a2 (the next three), so that the
      /// contact sees the current section; empty if the element has none.
      virtual std::vector<unsigned int>
      section_vector_components() const
      {
        return {};
      }
      /// True if the element carries a couple at its end ("End moment").
      virtual bool
      carries_moments() const
      {
        return false;
      }

      /**
       * Prepare the element of @p cable (section, Young's modulus) once its
       * mesh exists; @p length_ratio is rho = L_ref / L_0, the reference
       * over the unstressed length (prestress). Resets any state of the
       * last run (the end-moment tracking).
       */
      virtual void
      setup(const CableDefinition &cable, const double length_ratio) = 0;

      /// A new rho (a staged prestress, CableDefinition::prestress_factor)
      /// after setup(), keeping every other state.
      virtual void
      set_length_ratio(const double length_ratio) = 0;

      /**
       * Reference values of the components 3.. at @p node into @p values
       * (n_components() entries; 0-2 hold the position). Does nothing for
       * an element with the mid-line only. Throws InputError naming the
       * offending parameter.
       */
      virtual void
      reference_values(const CableNode &node, ArrayView<double> values) const;

      /**
       * The internal forces of one cell, added to @p cell_residual, their
       * derivative added to @p cell_matrix, and the cell values into
       * @p output (each may be nullptr). @p fe_values is reinit'ed on the
       * cell with quadrature(), values, gradients and JxW; @p tangent is
       * the unit reference tangent of the cell, along which d/dS is taken;
       * @p local_reference and @p local_u hold the reference values and
       * the unknowns at the cell's dofs.
       */
      virtual void
      cell_terms(const FEValues<1, 3> &fe_values,
                 const Tensor<1, 3>   &tangent,
                 const Vector<double> &local_reference,
                 const Vector<double> &local_u,
                 FullMatrix<double>   *cell_matrix,
                 Vector<double>       *cell_residual,
                 CableCellOutput      *output) const = 0;

      /**
       * A conservative couple @p moment [N m] on the end node: its terms
       * added to @p node_residual (n_components() values) and
       * @p node_matrix, at the node's reference values @p node_reference
       * and unknowns @p node_u. Only for carries_moments() (the default
       * throws).
       */
      virtual void
      end_moment_terms(const Tensor<1, 3>   &moment,
                       const Vector<double> &node_reference,
                       const Vector<double> &node_u,
                       FullMatrix<double>   *node_matrix,
                       Vector<double>       *node_residual) const;

      /**
       * Accept the converged end node (@p node_reference, @p node_u) under
       * @p moment, for the tracking of finite rotations, and return the
       * rotation of the end section about the moment axis since the start
       * [rad]. Only for carries_moments() (the default throws).
       */
      virtual double
      commit_end_moment(const Tensor<1, 3>   &moment,
                        const Vector<double> &node_reference,
                        const Vector<double> &node_u);

      /// The state commit_end_moment() tracks, for a checkpoint (none by
      /// default).
      virtual std::vector<double>
      committed_state() const
      {
        return {};
      }

      /// Restore committed_state() at a restart.
      virtual void
      restore_state(const std::vector<double> &state)
      {
        (void)state;
      }
    };

    /// The registry of cable elements.
    using CableElementRegistry = Registry<CableElement>;
  } // namespace cables
} // namespace pneuma
