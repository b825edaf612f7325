#include <deal.II/lac/lapack_full_matrix.h>

#include <pneuma/core/model.h>
#include <pneuma/solvers/stability.h>

#include <cmath>

namespace pneuma
{
  namespace solvers
  {
    namespace
    {
      /// Relative size below which a border eigenvalue or a deviation from
      /// proportionality is round-off.
      constexpr double round_off = 1e-8;

      /// Number of negative eigenvalues of the symmetric part of @p S.
      long long
      negative_eigenvalues(const FullMatrix<double> &S)
      {
        const unsigned int m = S.m();
        if (m == 0)
          return 0;
        LAPACKFullMatrix<double> lapack(m, m);
        double                   scale = 0.;
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            {
              lapack(i, j) = 0.5 * (S(i, j) + S(j, i));
              scale        = std::max(scale, std::abs(S(i, j)));
            }
        lapack.compute_eigenvalues();
        long long n = 0;
        for (unsigned int i = 0; i < m; ++i)
          if (lapack.eigenvalue(i).real() < -round_off * scale)
            ++n;
        return n;
      }
    } // namespace

    StabilityCheck::StabilityCheck(const MPI_Comm comm)
      : inertia(comm)
    {
    }

    StabilityReport
    StabilityCheck::check(Model &model, const BorderedVector &state)
    {
      TimerOutput::Scope t(model.timer(), "stability");
      StabilityReport    report;
      BorderedVector     residual;
      residual.field.reinit(state.field);
      model.assemble(state, residual);
      const LA::SparseMatrix &K = model.tangent_matrix();

      // How symmetric K is, on two fixed vectors.
      LA::Vector x(state.field), y(state.field), Kx(state.field),
        Ky(state.field);
      for (const auto i : model.locally_owned())
        {
          x[i] = std::sin(1.3 * i + 0.1);
          y[i] = std::cos(0.7 * i + 0.2);
        }
      x.compress(VectorOperation::insert);
      y.compress(VectorOperation::insert);
      K.vmult(Kx, x);
      K.vmult(Ky, y);
      report.asymmetry = std::abs(y * Kx - x * Ky)
                         / std::max(Kx.l2_norm() * y.l2_norm(), 1e-300);

      const Inertia k       = inertia.compute(K);
      report.negative_field = k.negative;
      report.zero           = k.zero;
      report.computed       = true;

      // The coupled chamber unknowns in energy form (see the header).
      const BorderCoupling     &c = model.border_coupling();
      std::vector<unsigned int> kept;
      std::vector<double>       alpha;
      for (unsigned int j = 0; j < c.size(); ++j)
        {
          if (!c.has_B[j] || !c.has_C[j])
            continue;
          const double CC = c.C[j] * c.C[j];
          if (CC == 0. || c.B[j].l2_norm() == 0.)
            continue;
          const double a = (c.B[j] * c.C[j]) / CC;
          LA::Vector   d(c.B[j]);
          d.add(-a, c.C[j]);
          if (d.l2_norm() > round_off * c.B[j].l2_norm())
            report.energy_form = false;
          kept.push_back(j);
          alpha.push_back(a);
        }
      const unsigned int m = kept.size();
      FullMatrix<double> AD(m, m), S(m, m);
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          AD(i, j) = alpha[i] * c.D(kept[i], kept[j]);
      if (m > 0)
        {
          if (k.zero > 0)
            report.note = "the field tangent is singular";
          // S = A D - B^T K^{-1} B: one substitution per unknown.
          std::vector<Vector<double>> B(m);
          for (unsigned int i = 0; i < m; ++i)
            B[i] = c.B[kept[i]];
          for (unsigned int j = 0; j < m; ++j)
            {
              Vector<double> z(B[j].size());
              inertia.solve(B[j], z);
              for (unsigned int i = 0; i < m; ++i)
                S(i, j) = AD(i, j) - B[i] * z;
            }
          FullMatrix<double> minus_AD(m, m);
          minus_AD.add(-1., AD);
          double scale = 0.;
          for (unsigned int i = 0; i < m; ++i)
            for (unsigned int j = 0; j < m; ++j)
              scale = std::max(scale, std::abs(AD(i, j)));
          if (scale > 0. && negative_eigenvalues(minus_AD) > 0)
            report.energy_form = false;
        }
      report.negative = k.negative + negative_eigenvalues(S) - m;
      if (!report.energy_form)
        {
          report.negative = -1;
          report.note = "the chamber terms are not of energy form (liquid and "
                        "gas in one chamber): only the count under "
                        "prescribed pressures is known";
        }
      if (report.asymmetry > round_off && report.note.empty())
        report.note = "the tangent is not symmetric (friction, or follower "
                      "pressure on free edges): the count is that of its "
                      "upper triangle";
      return report;
    }
  } // namespace solvers
} // namespace pneuma
