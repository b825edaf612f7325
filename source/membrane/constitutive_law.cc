#include <pneuma/core/input_error.h>
#include <pneuma/membrane/constitutive_law.h>

#include <cmath>

namespace pneuma
{
  namespace membrane
  {
    using namespace dealii;

    namespace
    {
      /// (A (.) A)_{ijkl} = (A_ik A_jl + A_il A_jk)/2: minus dA^{-1}/dA.
      SymmetricTensor<4, 2>
      symmetric_product(const SymmetricTensor<2, 2> &A)
      {
        SymmetricTensor<4, 2> R;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = i; j < 2; ++j)
            for (unsigned int k = 0; k < 2; ++k)
              for (unsigned int l = k; l < 2; ++l)
                R[i][j][k][l] = 0.5 * (A[i][k] * A[j][l] + A[i][l] * A[j][k]);
        return R;
      }
    } // namespace

    // ------------------------------------------------------------------
    StVenantKirchhoff::StVenantKirchhoff(const double E, const double nu_)
      : lambda_bar(E * nu_ / (1. - nu_ * nu_))
      , mu(E / (2. * (1. + nu_)))
      , nu(nu_)
    {
    }

    void
    StVenantKirchhoff::evaluate(const SymmetricTensor<2, 2> &C,
                                SymmetricTensor<2, 2>       &S,
                                SymmetricTensor<4, 2>       &D) const
    {
      const SymmetricTensor<2, 2> I = unit_symmetric_tensor<2>();
      const SymmetricTensor<2, 2> E = 0.5 * (C - I);
      S                             = lambda_bar * trace(E) * I + 2. * mu * E;
      D = lambda_bar * outer_product(I, I) + 2. * mu * identity_tensor<2>();
    }

    double
    StVenantKirchhoff::strain_energy(const SymmetricTensor<2, 2> &C) const
    {
      const SymmetricTensor<2, 2> E = 0.5 * (C - unit_symmetric_tensor<2>());
      return 0.5 * lambda_bar * trace(E) * trace(E) + mu * (E * E);
    }

    double
    StVenantKirchhoff::thickness_stretch(const SymmetricTensor<2, 2> &C) const
    {
      // Plane stress in the 3D law: E_33 = -nu/(1-nu) tr(E).
      const double E33 = -nu / (1. - nu) * 0.5 * (trace(C) - 2.);
      return std::sqrt(std::max(1. + 2. * E33, 0.));
    }

    double
    StVenantKirchhoff::initial_shear_modulus() const
    {
      return mu;
    }

    // ------------------------------------------------------------------
    IncompressibleMooneyRivlin::IncompressibleMooneyRivlin(const double c10_,
                                                           const double c01_)
      : c10(c10_)
      , c01(c01_)
    {
    }

    void
    IncompressibleMooneyRivlin::evaluate(const SymmetricTensor<2, 2> &C,
                                         SymmetricTensor<2, 2>       &S,
                                         SymmetricTensor<4, 2>       &D) const
    {
      const SymmetricTensor<2, 2> I    = unit_symmetric_tensor<2>();
      const double                detC = determinant(C);
      const SymmetricTensor<2, 2> Ci   = invert(C);
      const double                l3sq = 1. / detC;
      const double                trC  = trace(C);

      const SymmetricTensor<4, 2> CixCi = outer_product(Ci, Ci);
      const SymmetricTensor<4, 2> CioCi = symmetric_product(Ci);

      // dI1/dC, dI2/dC and their second derivatives (doc/theory.md).
      const SymmetricTensor<2, 2> dI1  = I - l3sq * Ci;
      const SymmetricTensor<2, 2> dI2  = detC * Ci + l3sq * I - trC * l3sq * Ci;
      const SymmetricTensor<4, 2> ddI1 = l3sq * (CixCi + CioCi);
      const SymmetricTensor<4, 2> ddI2 =
        detC * (CixCi - CioCi)
        - l3sq * (outer_product(I, Ci) + outer_product(Ci, I))
        + trC * l3sq * (CixCi + CioCi);

      S = 2. * (c10 * dI1 + c01 * dI2);
      D = 4. * (c10 * ddI1 + c01 * ddI2);
    }

    double
    IncompressibleMooneyRivlin::strain_energy(
      const SymmetricTensor<2, 2> &C) const
    {
      const double detC = determinant(C);
      const double l3sq = 1. / detC;
      const double I1   = trace(C) + l3sq;
      const double I2   = detC + l3sq * trace(C);
      return c10 * (I1 - 3.) + c01 * (I2 - 3.);
    }

    double
    IncompressibleMooneyRivlin::thickness_stretch(
      const SymmetricTensor<2, 2> &C) const
    {
      return 1. / std::sqrt(determinant(C));
    }

    double
    IncompressibleMooneyRivlin::initial_shear_modulus() const
    {
      return 2. * (c10 + c01);
    }

    // ------------------------------------------------------------------
    std::string
    MaterialRegions::law_names()
    {
      return "St. Venant-Kirchhoff|neo-Hookean|Mooney-Rivlin";
    }

    void
    MaterialRegions::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      for (unsigned int r = 0; r < max_regions; ++r)
        {
          prm.enter_subsection("Region " + std::to_string(r));
          prm.declare_entry("Law",
                            "St. Venant-Kirchhoff",
                            Patterns::Selection(law_names()),
                            "Membrane law of the cells with material id "
                              + std::to_string(r)
                              + ". neo-Hookean and Mooney-Rivlin are "
                                "incompressible (plane stress exact).");
          prm.declare_entry("Thickness",
                            "1e-3",
                            Patterns::Double(),
                            "Reference wall thickness H [m]; must be > 0.");
          prm.declare_entry("Density",
                            "0",
                            Patterns::Double(0.),
                            "Mass density [kg/m^3] (gravity, mass matrix).");
          prm.declare_entry("Young's modulus",
                            "7.6e9",
                            Patterns::Double(),
                            "E [Pa] of St. Venant-Kirchhoff; must be > 0.");
          prm.declare_entry("Poisson's ratio",
                            "0.3",
                            Patterns::Double(-1., 0.5),
                            "nu [-] of St. Venant-Kirchhoff.");
          prm.declare_entry("Shear modulus",
                            "1e6",
                            Patterns::Double(),
                            "mu [Pa] of neo-Hookean (W = mu/2 (I1-3)); "
                            "must be > 0.");
          prm.declare_entry("C10",
                            "4e5",
                            Patterns::Double(),
                            "C10 [Pa] of Mooney-Rivlin, "
                            "W = C10 (I1-3) + C01 (I2-3).");
          prm.declare_entry("C01",
                            "1e5",
                            Patterns::Double(),
                            "C01 [Pa] of Mooney-Rivlin.");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    void
    MaterialRegions::parse_parameters(ParameterHandler &prm)
    {
      regions.clear();
      prm.enter_subsection("Materials");
      for (unsigned int r = 0; r < max_regions; ++r)
        {
          const std::string path = "Materials/Region " + std::to_string(r);
          prm.enter_subsection("Region " + std::to_string(r));
          RegionMaterial m;
          m.law_name  = prm.get("Law");
          m.thickness = prm.get_double("Thickness");
          m.density   = prm.get_double("Density");
          check_input(m.thickness > 0.,
                      path + "/Thickness",
                      "must be positive, got " + prm.get("Thickness"));
          if (m.law_name == "St. Venant-Kirchhoff")
            {
              const double E = prm.get_double("Young's modulus");
              check_input(E > 0.,
                          path + "/Young's modulus",
                          "must be positive, got "
                            + prm.get("Young's modulus"));
              m.law = std::make_shared<StVenantKirchhoff>(
                E, prm.get_double("Poisson's ratio"));
            }
          else if (m.law_name == "neo-Hookean")
            {
              const double mu = prm.get_double("Shear modulus");
              check_input(mu > 0.,
                          path + "/Shear modulus",
                          "must be positive, got " + prm.get("Shear modulus"));
              m.law = std::make_shared<IncompressibleMooneyRivlin>(mu / 2., 0.);
            }
          else
            {
              const double c10 = prm.get_double("C10");
              const double c01 = prm.get_double("C01");
              check_input(c10 + c01 > 0. && c10 >= 0. && c01 >= 0.,
                          path + "/C10",
                          "C10 and C01 must be >= 0 with C10 + C01 > 0");
              m.law = std::make_shared<IncompressibleMooneyRivlin>(c10, c01);
            }
          regions.push_back(m);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    const RegionMaterial &
    MaterialRegions::operator[](const unsigned int id) const
    {
      check_input(id < regions.size(),
                  "Materials",
                  "the mesh has a cell with material id " + std::to_string(id)
                    + " but only regions 0.." + std::to_string(max_regions - 1)
                    + " can be set");
      return regions[id];
    }
  } // namespace membrane
} // namespace pneuma
