#include <pneuma/core/model.h>
#include <pneuma/solvers/path_following.h>

#include <cmath>

namespace pneuma
{
  namespace solvers
  {
    PathConstraintProblem::PathConstraintProblem(Model &model, const double h)
      : model(model)
      , h(h)
    {
    }

    BorderedVector
    PathConstraintProblem::extend(const BorderedVector &state, const double t)
    {
      BorderedVector x;
      x.field = state.field;
      x.border.reinit(state.border.size() + 1);
      for (unsigned int j = 0; j < state.border.size(); ++j)
        x.border[j] = state.border[j];
      x.border[state.border.size()] = t;
      return x;
    }

    BorderedVector
    PathConstraintProblem::model_part(const BorderedVector &x)
    {
      BorderedVector state;
      state.field = x.field;
      state.border.reinit(x.border.size() - 1);
      for (unsigned int j = 0; j + 1 < x.border.size(); ++j)
        state.border[j] = x.border[j];
      return state;
    }

    void
    PathConstraintProblem::set_scales(const double u_s,
                                      const double p2,
                                      const double f,
                                      const double rate)
    {
      u_scale      = u_s;
      psi2         = p2;
      force        = f;
      monitor_rate = rate;
    }

    void
    PathConstraintProblem::set_constraint(const Control         type,
                                          const BorderedVector &c,
                                          const double          size)
    {
      control = type;
      center  = c;
      set_size(size);
    }

    double
    PathConstraintProblem::dot(const BorderedVector &a,
                               const BorderedVector &b) const
    {
      return (a.field * b.field / (u_scale * u_scale)
              + psi2 * load_factor(a) * load_factor(b))
             / (1. + psi2);
    }

    double
    PathConstraintProblem::arc_length(const BorderedVector &dx) const
    {
      return std::sqrt(std::max(dot(dx, dx), 0.));
    }

    double
    PathConstraintProblem::radius_at(const LA::Vector &field,
                                     const double      tau,
                                     LA::Vector       &du) const
    {
      du = field;
      du -= center.field;
      const double dt = tau - load_factor(center);
      return std::sqrt(
        std::max((du * du / (u_scale * u_scale) + psi2 * dt * dt) / (1. + psi2),
                 0.));
    }

    double
    PathConstraintProblem::constraint(const BorderedVector &x) const
    {
      LA::Vector du;
      if (control == Control::displacement)
        {
          du = x.field;
          du -= center.field;
          return (w * du - increment) / monitor_rate;
        }
      return radius_at(x.field, load_factor(x), du) - radius;
    }

    void
    PathConstraintProblem::assemble_model(const BorderedVector &x)
    {
      last_x = model_part(x);
      last_r = last_x;
      model.assemble(last_x, load_factor(x), last_r);
      rate_current = false;
    }

    void
    PathConstraintProblem::assemble(const BorderedVector &x,
                                    BorderedVector       &residual)
    {
      assemble_model(x);
      residual = extend(last_r, force * constraint(x));
    }

    void
    PathConstraintProblem::update_rate()
    {
      if (rate_current)
        return;
      const double t = model.time();
      rate           = last_r;
      model.assemble_residual(last_x, t + h, rate);
      rate -= last_r;
      rate *= 1. / h;
      rate_current = true;
    }

    BorderedVector
    PathConstraintProblem::tangent(const BorderedVector &x, double &force_rate)
    {
      assemble_model(x);
      update_rate();
      force_rate = rate.l2_norm();
      BorderedVector rhs(rate), t(rate);
      rhs *= -1.;
      model.solve_linear(0., rhs, t);
      return t;
    }

    void
    PathConstraintProblem::solve_linear(const double          shift,
                                        const BorderedVector &rhs,
                                        BorderedVector       &dx)
    {
      // J a = r_u, J b = dR/dtau on one factorization.
      BorderedVector a(last_r), b(last_r);
      model.solve_linear(shift, model_part(rhs), a);
      update_rate();
      model.solve_again(rate, b);

      // The constraint row: g_u . du + g_tau dtau = r_g / F.
      const Gradient g           = gradient();
      const double   r_g         = load_factor(rhs) / force;
      const double   g_a         = g.scale * (g.direction * a.field);
      const double   g_b         = g.scale * (g.direction * b.field);
      const double   denominator = g.tau - g_b;
      const double   dtau = denominator != 0. ? (r_g - g_a) / denominator : 0.;
      a.add(-dtau, b);
      dx = extend(a, dtau);
    }

    PathConstraintProblem::Gradient
    PathConstraintProblem::gradient() const
    {
      Gradient g;
      if (control == Control::displacement)
        {
          g.direction = w;
          g.scale     = 1. / monitor_rate;
          return g;
        }
      const double s =
        std::max(radius_at(last_x.field, model.time(), g.direction), 1e-300);
      g.scale = 1. / (u_scale * u_scale * (1. + psi2) * s);
      g.tau   = psi2 * (model.time() - load_factor(center)) / ((1. + psi2) * s);
      return g;
    }

    void
    PathConstraintProblem::vmult(const BorderedVector &d, BorderedVector &y)
    {
      BorderedVector       ym(last_r);
      const BorderedVector dm = model_part(d);
      model.vmult(dm, ym);
      update_rate();
      ym.add(load_factor(d), rate);
      const Gradient g = gradient();
      y                = extend(
        ym,
        force * (g.scale * (g.direction * d.field) + g.tau * load_factor(d)));
    }

    double
    PathConstraintProblem::initial_shift(const double factor)
    {
      return model.initial_shift(factor);
    }

    void
    PathConstraintProblem::laplacian_vmult(const BorderedVector &x,
                                           BorderedVector       &y)
    {
      BorderedVector ym(last_r);
      model.laplacian_vmult(model_part(x), ym);
      y = extend(ym, 0.);
    }

    double
    PathConstraintProblem::start_prestress()
    {
      return model.start_prestress();
    }

    double
    PathConstraintProblem::load_norm()
    {
      return model.load_norm();
    }

    void
    PathConstraintProblem::set_linear_tolerance(const double eta)
    {
      model.set_linear_tolerance(eta);
    }

    bool
    PathConstraintProblem::interrupted()
    {
      return model.interrupted();
    }

    std::vector<std::string>
    PathConstraintProblem::block_names() const
    {
      auto names = model.block_names();
      names.push_back("path");
      return names;
    }

    std::vector<double>
    PathConstraintProblem::block_norms(const BorderedVector &r) const
    {
      auto norms = model.block_norms(model_part(r));
      norms.push_back(std::abs(load_factor(r)));
      return norms;
    }
  } // namespace solvers
} // namespace pneuma
