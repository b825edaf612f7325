#pragma once

/**
 * @file
 * Hyperelastic plane-stress membrane laws written in a local orthonormal
 * basis of the reference tangent plane, and the material regions of the
 * membrane (doc/theory.md "Membrane laws").
 *
 * The membrane strain is the surface Green-Lagrange tensor
 * \f$E = \tfrac12(C - I)\f$ with the 2x2 right Cauchy-Green tensor
 * \f$C_{\alpha\beta} = a_\alpha\cdot a_\beta\f$, where \f$a_\alpha = F
 * e_\alpha\f$ are the deformed images of the reference tangent unit vectors.
 * Every law returns the second Piola-Kirchhoff stress \f$S\f$ per unit
 * reference volume and its consistent tangent \f$\mathbb{D} = \partial
 * S/\partial E\f$; the membrane force per unit reference length is \f$H S\f$.
 *
 * A law is one .cc file in source/membrane/laws/ with one registration line
 * (core/registry.h); its constants live in the subsection of its name,
 * e.g. "Materials/Region 0/neo-Hookean/Shear modulus".
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <pneuma/core/registry.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pneuma
{
  class InputLayout;

  namespace membrane
  {
    using dealii::SymmetricTensor;

    /// A plane-stress hyperelastic membrane law.
    class ConstitutiveLaw
    {
    public:
      virtual ~ConstitutiveLaw() = default;

      /// Declare (and bind) the law's constants in the current subsection.
      virtual void
      declare_parameters(dealii::ParameterHandler &prm) = 0;
      /// Check the constants; messages name @p path.
      virtual void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path) = 0;

      /// Stress S and tangent dS/dE at the 2x2 right Cauchy-Green tensor C.
      virtual void
      evaluate(const SymmetricTensor<2, 2> &C,
               SymmetricTensor<2, 2>       &S,
               SymmetricTensor<4, 2>       &dS_dE) const = 0;

      /// The stress S alone at @p C (an assembly without a matrix); the
      /// default evaluates the tangent too.
      virtual void
      stress(const SymmetricTensor<2, 2> &C, SymmetricTensor<2, 2> &S) const
      {
        SymmetricTensor<4, 2> D;
        evaluate(C, S, D);
      }

      /// Strain energy per unit reference volume.
      virtual double
      strain_energy(const SymmetricTensor<2, 2> &C) const = 0;

      /// Thickness stretch lambda_3 = h/H from the plane-stress condition.
      virtual double
      thickness_stretch(const SymmetricTensor<2, 2> &C) const = 0;

      /// Initial (small-strain) in-plane shear modulus, for scaling.
      virtual double
      initial_shear_modulus() const = 0;

      /// Whether the law is isotropic in the tangent plane (else it is
      /// written in the region's material frame, e_1 along the warp).
      virtual bool
      isotropic() const
      {
        return true;
      }
    };

    /// The registry of membrane laws.
    using LawRegistry = Registry<ConstitutiveLaw>;

    class TensionFieldLaw;

    /// The material of one region (material id) of the membrane mesh.
    /// Membrane strains = auto (assumed on Q2 shells, else the
    /// displacement's), displacement or assumed.
    enum class MembraneStrains
    {
      automatic,
      displacement,
      assumed
    };

    struct RegionMaterial
    {
      std::string                      law_name;
      double                           thickness = 1e-3;
      double                           density   = 0.;
      std::shared_ptr<ConstitutiveLaw> law;
      /// The law relaxed by tension field theory (the same object as law)
      /// where the region wrinkles, else null.
      std::shared_ptr<const TensionFieldLaw> tension_field;
      /// The law without tension field theory (law itself where the region
      /// does not wrinkle): the stiffest tangent a point can have (the
      /// fictitious mass of dynamic relaxation).
      std::shared_ptr<ConstitutiveLaw> plain_law;
      /// The warp direction whose projection onto the tangent plane is the
      /// frame's e_1 (zero: none, the frame follows the normal only).
      dealii::Tensor<1, 3> warp_direction;
      /// The warp comes from the mesh file (Warp direction = gmsh: the
      /// Gmsh $ElementData view "warp"), per cell.
      bool warp_from_mesh = false;
      /// The warp direction of @p cell: the mesh's (@p geometry's
      /// cell_direction) if warp_from_mesh, else warp_direction.
      template <class Geometry, class Iterator>
      dealii::Tensor<1, 3>
      warp(const Geometry &geometry, const Iterator &cell) const
      {
        return warp_from_mesh ? geometry.cell_direction(cell) : warp_direction;
      }
      /// The prestress n_1, n_2 [N/m] along warp and fill (also the target
      /// of form finding).
      std::array<double, 2> prestress{{0., 0.}};
      /// Bending = shell: the factor on the bending stiffness t^3/12 dS/dE
      /// (membrane/bending/shell_bending.h); 0: a membrane.
      double bending_factor = 0.;
      /// The membrane strains of the region's Q2 cells: the displacement's
      /// own, or assumed strains interpolated from tying points (MITC9,
      /// membrane/assumed_strains.h), which remove membrane locking of
      /// curved shells.
      MembraneStrains membrane_strains = MembraneStrains::automatic;
    };

    /**
     * The material regions of the membrane: "Materials/Region <id>" for
     * every material id the input names (any non-negative integer, e.g. the
     * tags of Gmsh physical surfaces), each with its law and the law's
     * constants.
     */
    class MaterialRegions
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm,
                         const InputLayout        &layout);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// Material of region (material id) @p id; InputError if the input
      /// has no "Materials/Region <id>".
      const RegionMaterial &
      operator[](const dealii::types::material_id id) const;

      /// The ids of the regions the input declares.
      std::vector<dealii::types::material_id>
      ids() const;

      /// Whether any region wrinkles (tension field theory).
      bool
      any_wrinkling() const;
      /// Whether any region is a shell (has bending).
      bool
      any_bending() const;

    private:
      /// One declared region: bound values and every law's constants.
      struct Slot
      {
        dealii::types::material_id id;
        std::string                law       = "Saint Venant-Kirchhoff";
        double                     thickness = 1e-3;
        double                     density   = 0.;
        /// Wrinkling: none (false) or tension field (true).
        bool        wrinkling = false;
        std::string warp_direction;
        std::string prestress          = "0";
        double      residual_stiffness = 1e-6;
        double      smoothing          = 0.;
        /// Bending: none (false) or shell (true), and its factor.
        bool            bending          = false;
        double          bending_factor   = 1.;
        MembraneStrains membrane_strains = MembraneStrains::automatic;
        std::map<std::string, std::unique_ptr<ConstitutiveLaw>> laws;
      };
      std::vector<std::unique_ptr<Slot>>                   slots;
      std::map<dealii::types::material_id, RegionMaterial> regions;
    };
  } // namespace membrane
} // namespace pneuma
