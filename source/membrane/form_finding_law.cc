#include <deal.II/base/exceptions.h>

#include <pneuma/membrane/form_finding_law.h>

#include <cmath>

namespace pneuma
{
  namespace membrane
  {
    FormFindingLaw::FormFindingLaw(const double n1,
                                   const double n2,
                                   const double lambda,
                                   const double H)
      : n1(n1)
      , n2(n2)
      , lambda(lambda)
      , H(H)
    {
      Assert(lambda >= 0. && lambda < 1., dealii::ExcInternalError());
      Assert(lambda == 0. || n1 == n2, dealii::ExcInternalError());
    }

    void
    FormFindingLaw::evaluate(const SymmetricTensor<2, 2> &C,
                             SymmetricTensor<2, 2>       &S,
                             SymmetricTensor<4, 2>       &D) const
    {
      // The constant part (1 - lambda) S_0.
      S       = 0;
      D       = 0;
      S[0][0] = (1. - lambda) * n1 / H;
      S[1][1] = (1. - lambda) * n2 / H;
      if (lambda == 0.)
        return;

      // The Cauchy part lambda S_c(C) and its derivatives by C_11 = a,
      // C_22 = b and C_12 = c (doc/theory.md "Form finding").
      const double a = C[0][0], b = C[1][1], c = C[0][1];
      const double s  = std::sqrt(a * b - c * c);
      const double s3 = s * s * s;
      const double f  = lambda / H;

      S[0][0] += f * (n1 * s / a + n2 * c * c / (a * s));
      S[0][1] += f * (-n2 * c / s);
      S[1][1] += f * (n2 * a / s);

      // dS/da, dS/db, dS/dc for the components 00, 01, 11.
      const double d00_a =
        n1 * (b / (2. * s * a) - s / (a * a))
        + n2 * c * c * (-1. / (a * a * s) - b / (2. * a * s3));
      const double d00_b = n1 / (2. * s) - n2 * c * c / (2. * s3);
      const double d00_c =
        -n1 * c / (s * a) + n2 * (2. * c / (a * s) + c * c * c / (a * s3));
      const double d01_a = n2 * c * b / (2. * s3);
      const double d01_b = n2 * c * a / (2. * s3);
      const double d01_c = -n2 * (1. / s + c * c / s3);
      const double d11_a = n2 * (1. / s - a * b / (2. * s3));
      const double d11_b = -n2 * a * a / (2. * s3);
      const double d11_c = n2 * a * c / s3;

      // dS_ij = D_ijkl dE_kl with dE = dC/2 and both off-diagonal entries.
      D[0][0][0][0] = 2. * f * d00_a;
      D[0][0][1][1] = 2. * f * d00_b;
      D[0][0][0][1] = f * d00_c;
      D[0][1][0][0] = 2. * f * d01_a;
      D[0][1][1][1] = 2. * f * d01_b;
      D[0][1][0][1] = f * d01_c;
      D[1][1][0][0] = 2. * f * d11_a;
      D[1][1][1][1] = 2. * f * d11_b;
      D[1][1][0][1] = f * d11_c;
    }

    double
    FormFindingLaw::strain_energy(const SymmetricTensor<2, 2> &C) const
    {
      const double E11 = 0.5 * (C[0][0] - 1.), E22 = 0.5 * (C[1][1] - 1.);
      return ((1. - lambda) * (n1 * E11 + n2 * E22)
              + lambda * n1 * (std::sqrt(determinant(C)) - 1.))
             / H;
    }
  } // namespace membrane
} // namespace pneuma
