#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/hp/q_collection.h>

#include <pneuma/chambers/free_surface_quadrature.h>

#include <algorithm>
#include <cmath>

namespace pneuma
{
  namespace chambers
  {
    namespace
    {
      /// psi(xi) = sum_k psi_k N_k(xi) on the reference cell.
      class InterpolatedLevelSet : public Function<2>
      {
      public:
        InterpolatedLevelSet(const FE_Q<2> &fe, const std::vector<double> &c)
          : fe(fe)
          , c(c)
        {
        }
        double
        value(const Point<2> &p, const unsigned int = 0) const override
        {
          double v = 0.;
          for (unsigned int k = 0; k < c.size(); ++k)
            v += c[k] * fe.shape_value(k, p);
          return v;
        }
        Tensor<1, 2>
        gradient(const Point<2> &p, const unsigned int = 0) const override
        {
          Tensor<1, 2> g;
          for (unsigned int k = 0; k < c.size(); ++k)
            g += c[k] * fe.shape_grad(k, p);
          return g;
        }
        SymmetricTensor<2, 2>
        hessian(const Point<2> &p, const unsigned int = 0) const override
        {
          Tensor<2, 2> h;
          for (unsigned int k = 0; k < c.size(); ++k)
            h += c[k] * fe.shape_grad_grad(k, p);
          return symmetrize(h);
        }

      private:
        const FE_Q<2>             &fe;
        const std::vector<double> &c;
      };
    } // namespace

    FreeSurfaceQuadrature::FreeSurfaceQuadrature(const unsigned int degree,
                                                 const unsigned int n_points)
      : fe(degree)
      , points(fe.get_unit_support_points())
      , quadrature_1d(QGauss<1>(n_points))
      , generator(quadrature_1d)
    {
    }

    FreeSurfaceQuadrature::Location
    FreeSurfaceQuadrature::classify(const std::vector<double> &psi_in)
    {
      // The generator (deal.II 9.4) fails on roots at or next to a
      // vertex (e.g. a clamped rim exactly at the level): such values are
      // moved off zero by a negligible amount, to the side of the other
      // nodes, so that a cell touching the level at a vertex is not cut.
      psi                   = psi_in;
      const auto [lo0, hi0] = std::minmax_element(psi.begin(), psi.end());
      const double tiny     = 1e-12 * std::max(*hi0 - *lo0, 1e-300);
      double       others   = 0.;
      for (const auto v : psi)
        if (std::abs(v) >= tiny)
          others += v;
      for (auto &v : psi)
        if (std::abs(v) < tiny)
          v = others < 0. ? -tiny : tiny;
      const auto [lo, hi] = std::minmax_element(psi.begin(), psi.end());
      // A bilinear psi takes its extremes at the vertices; a higher-degree
      // one may dip between nodes, so near-zero cells go to the generator,
      // which detects definite cells itself.
      const double margin = fe.degree == 1 ? 0. : 0.25 * (*hi - *lo);
      if (*lo > margin)
        return Location::dry;
      if (*hi < -margin)
        return Location::wet;
      const InterpolatedLevelSet level_set(fe, psi);
      const BoundingBox<2>       unit(
        std::make_pair(Point<2>(0., 0.), Point<2>(1., 1.)));
      generator.generate(level_set, unit);
      if (wet_quadrature().size() == 0)
        return Location::dry;
      if (generator.get_outside_quadrature().size() == 0)
        return Location::wet;
      return Location::cut;
    }
  } // namespace chambers
} // namespace pneuma
