#pragma once

/**
 * @file
 * The exact gradient and Hessian of a point energy by Sacado's forward
 * numbers of fixed size (forward over forward for the Hessian, as deal.II's
 * step-72 does with its AD helpers): included only by the bending terms'
 * sources, where the energies are instantiated.
 */

#include <deal.II/base/config.h>

#ifndef DEAL_II_TRILINOS_WITH_SACADO
#error "pneuma's shell bending needs deal.II with Trilinos Sacado"
#endif

#include <Sacado.hpp>

#include <array>

namespace pneuma
{
  namespace membrane
  {
    namespace bending
    {
      /**
       * The energy @p f (a generic callable of a pointer to N numbers) at
       * @p x: returns its value, writes its gradient to @p gradient and,
       * if @p hessian is not null, its Hessian (row-major N x N).
       */
      template <int N, typename F>
      double
      differentiate(const double *x,
                    const F      &f,
                    double       *gradient,
                    double       *hessian)
      {
        using Inner = Sacado::Fad::SFad<double, N>;
        if (hessian == nullptr)
          {
            std::array<Inner, N> v;
            for (int k = 0; k < N; ++k)
              v[k] = Inner(N, k, x[k]);
            const Inner e = f(v.data());
            for (int k = 0; k < N; ++k)
              gradient[k] = e.dx(k);
            return e.val();
          }
        using Outer = Sacado::Fad::SFad<Inner, N>;
        std::array<Outer, N> v;
        for (int k = 0; k < N; ++k)
          v[k] = Outer(N, k, Inner(N, k, x[k]));
        const Outer e = f(v.data());
        for (int k = 0; k < N; ++k)
          {
            gradient[k] = e.val().dx(k);
            for (int l = 0; l < N; ++l)
              hessian[k * N + l] = e.dx(k).dx(l);
          }
        return e.val().val();
      }
    } // namespace bending
  }   // namespace membrane
} // namespace pneuma
