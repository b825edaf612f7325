#pragma once

/**
 * @file
 * Hyperelastic plane-stress membrane laws written in a local orthonormal
 * basis of the reference tangent plane.
 *
 * The membrane strain is the surface Green-Lagrange tensor
 * \f$E = \tfrac12(C - I)\f$ with the 2x2 right Cauchy-Green tensor
 * \f$C_{\alpha\beta} = a_\alpha\cdot a_\beta\f$, where \f$a_\alpha = F
 * e_\alpha\f$ are the deformed images of the reference tangent unit vectors.
 * Every law returns the second Piola-Kirchhoff stress \f$S\f$ per unit
 * reference volume and its consistent tangent \f$\mathbb{D} = \partial
 * S/\partial E\f$; the membrane force per unit reference length is \f$H S\f$.
 *
 * Plane stress is built in: for the incompressible laws the thickness
 * stretch is eliminated exactly, \f$\lambda_3^2 = 1/\det C\f$; for St.
 * Venant-Kirchhoff the reduced plane-stress modulus is used. Theory in
 * doc/theory.md, section "Membrane laws".
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <memory>
#include <string>

namespace pneuma
{
  namespace membrane
  {
    using dealii::SymmetricTensor;

    /// A plane-stress hyperelastic membrane law.
    class ConstitutiveLaw
    {
    public:
      virtual ~ConstitutiveLaw() = default;

      /// Stress S and tangent dS/dE at the 2x2 right Cauchy-Green tensor C.
      virtual void
      evaluate(const SymmetricTensor<2, 2> &C,
               SymmetricTensor<2, 2>       &S,
               SymmetricTensor<4, 2>       &dS_dE) const = 0;

      /// Strain energy per unit reference volume.
      virtual double
      strain_energy(const SymmetricTensor<2, 2> &C) const = 0;

      /// Thickness stretch lambda_3 = h/H from the plane-stress condition.
      virtual double
      thickness_stretch(const SymmetricTensor<2, 2> &C) const = 0;

      /// Initial (small-strain) in-plane shear modulus, for scaling.
      virtual double
      initial_shear_modulus() const = 0;
    };

    /**
     * St. Venant-Kirchhoff in plane stress:
     * \f$S = \bar\lambda\,\mathrm{tr}E\,I + 2\mu E\f$,
     * \f$\bar\lambda = E\nu/(1-\nu^2)\f$, \f$\mu = E/(2(1+\nu))\f$.
     */
    class StVenantKirchhoff : public ConstitutiveLaw
    {
    public:
      StVenantKirchhoff(const double youngs_modulus, const double poisson);
      void
      evaluate(const SymmetricTensor<2, 2> &C,
               SymmetricTensor<2, 2>       &S,
               SymmetricTensor<4, 2>       &dS_dE) const override;
      double
      strain_energy(const SymmetricTensor<2, 2> &C) const override;
      double
      thickness_stretch(const SymmetricTensor<2, 2> &C) const override;
      double
      initial_shear_modulus() const override;

    private:
      double lambda_bar, mu, nu;
    };

    /**
     * Incompressible Mooney-Rivlin in plane stress,
     * \f$W = C_{10}(I_1 - 3) + C_{01}(I_2 - 3)\f$ with
     * \f$I_1 = \mathrm{tr}C + \lambda_3^2\f$,
     * \f$I_2 = \det C + \lambda_3^2\,\mathrm{tr}C\f$,
     * \f$\lambda_3^2 = 1/\det C\f$. With \f$C_{01} = 0\f$ and
     * \f$C_{10} = \mu/2\f$ it is the incompressible neo-Hookean law
     * \f$S = \mu(I - \lambda_3^2 C^{-1})\f$.
     */
    class IncompressibleMooneyRivlin : public ConstitutiveLaw
    {
    public:
      IncompressibleMooneyRivlin(const double c10, const double c01);
      void
      evaluate(const SymmetricTensor<2, 2> &C,
               SymmetricTensor<2, 2>       &S,
               SymmetricTensor<4, 2>       &dS_dE) const override;
      double
      strain_energy(const SymmetricTensor<2, 2> &C) const override;
      double
      thickness_stretch(const SymmetricTensor<2, 2> &C) const override;
      double
      initial_shear_modulus() const override;

    private:
      double c10, c01;
    };

    /**
     * The material of one region (material id) of the membrane mesh: its
     * law, thickness and density, read from "Materials/Region N".
     */
    struct RegionMaterial
    {
      std::string                      law_name;
      double                           thickness = 1e-3;
      double                           density   = 0.;
      std::shared_ptr<ConstitutiveLaw> law;
    };

    /// The material regions of the membrane: "Materials/Region 0..N".
    class MaterialRegions
    {
    public:
      /// Number of region slots that can be set in a parameter file.
      static constexpr unsigned int max_regions = 16;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// Material of region (material id) @p id.
      const RegionMaterial &
      operator[](const unsigned int id) const;

      /// Names of all law choices, for the Patterns::Selection.
      static std::string
      law_names();

    private:
      std::vector<RegionMaterial> regions;
    };
  } // namespace membrane
} // namespace pneuma
