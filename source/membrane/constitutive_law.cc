#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/selection_parameter.h>
#include <pneuma/membrane/constitutive_law.h>
#include <pneuma/membrane/prestress.h>
#include <pneuma/membrane/tension_field.h>

#include <deal.II/base/utilities.h>

#include <cmath>

namespace pneuma
{
  namespace membrane
  {
    using namespace dealii;

    void
    MaterialRegions::declare_parameters(ParameterHandler  &prm,
                                        const InputLayout &layout)
    {
      slots.clear();
      const auto &laws = LawRegistry::instance();
      prm.enter_subsection("Materials");
      for (const auto id : layout.keyed("Materials", "Region", {0}))
        {
          auto slot = std::make_unique<Slot>();
          slot->id  = id;
          prm.enter_subsection("Region " + std::to_string(id));
          prm.add_parameter("Law",
                            slot->law,
                            "Membrane law of the cells with this material id "
                            "(Gmsh physical surface tag); its constants are "
                            "in the subsection of its name. "
                              + laws.descriptions() + ".",
                            Patterns::Selection(laws.names()));
          prm.add_parameter("Thickness",
                            slot->thickness,
                            "Reference wall thickness H [m]; must be > 0.",
                            Patterns::Double());
          prm.add_parameter(
            "Density",
            slot->density,
            "Mass density [kg/m^3]: gravity, and the mass of a modal "
            "analysis (density * thickness per reference "
            "area).",
            Patterns::Double(0.));
          add_selection(
            prm,
            "Wrinkling",
            slot->wrinkling,
            {{"none", false}, {"tension field", true}},
            "none: the law carries compression; tension field: the "
            "membrane wrinkles instead (relaxed energy of tension field "
            "theory, any law): every point is taut, wrinkled (uniaxial "
            "tension) or slack, shown by the VTU fields wrinkling_state, "
            "wrinkle_direction and relaxed_compression.");
          prm.add_parameter(
            "Wrinkling residual stiffness",
            slot->residual_stiffness,
            "Fraction eps of the plain law kept where wrinkled or slack "
            "(energy W_relaxed + eps W), so that a slack patch keeps a "
            "regular tangent; 0 <= eps < 1e-2.",
            Patterns::Double(0.));
          prm.add_parameter(
            "Wrinkling smoothing",
            slot->smoothing,
            "Strain width zeta over which the relaxed energy is smoothed "
            "(an interior-point barrier d zeta^2/4, d the law's stiffest "
            "modulus, doc/theory.md 2.1): the tangent becomes continuous "
            "through state "
            "changes; the stress of a taut point changes by about "
            "(zeta/strain)^2 of itself. 0: the exact relaxed energy.",
            Patterns::Double(0., 1e-2));
          add_selection(
            prm,
            "Bending",
            slot->bending,
            {{"none", false}, {"shell", true}},
            "none: a membrane (no bending stiffness); shell: a "
            "Kirchhoff-Love shell, the membrane law plus the bending "
            "energy of the change of curvature with D = t^3/12 dS/dE of the "
            "law at zero strain (section Bending, doc/theory.md 21). With "
            "Wrinkling = tension field and a small Bending stiffness factor "
            "it is a wrinkling wall that keeps some bending stiffness (a "
            "regulariser of crumpled and slack states).");
          prm.add_parameter(
            "Bending stiffness factor",
            slot->bending_factor,
            "Factor on the shell's bending stiffness t^3/12 dS/dE: 1 for the "
            "wall's own bending, below 1 for bending as a regulariser; > 0.",
            Patterns::Double());
          add_selection(
            prm,
            "Membrane strains",
            slot->membrane_strains,
            {{"auto", MembraneStrains::automatic},
             {"displacement", MembraneStrains::displacement},
             {"assumed", MembraneStrains::assumed}},
            "The membrane strains of Q2 cells. displacement: those of the "
            "displacement field; assumed: interpolated from tying points "
            "(MITC9, Bucalem & Bathe 1993; doc/theory.md 21), which removes "
            "the membrane locking of curved shells on coarse meshes; auto: "
            "assumed where the region is a shell, else displacement. Q1 "
            "cells always use the displacement's strains.");
          prm.add_parameter(
            "Warp direction",
            slot->warp_direction,
            "A vector 'x, y, z' whose projection onto the surface is the "
            "material frame's first axis (the warp of a fabric; the fill "
            "is normal to it in the surface), e.g. '1, 0, 0' along a tube "
            "on the x axis; or 'gmsh': per element, the vector of the "
            "Gmsh mesh file's $ElementData view named \"warp\" (panels "
            "cut in different directions). Required by the orthotropic "
            "law and by an unequal prestress; it must not be normal to "
            "the surface anywhere in the region.",
            Patterns::Anything());
          prm.add_parameter(
            "Prestress",
            slot->prestress,
            "Membrane forces of the reference state [N/m]: 'n' "
            "(isotropic) or 'n1, n2' along the warp and the fill (needs a "
            "Warp direction); added to the law's stress.",
            Patterns::Anything());
          slot->laws = laws.declare_all(prm);
          prm.leave_subsection();
          slots.push_back(std::move(slot));
        }
      prm.leave_subsection();
    }

    void
    MaterialRegions::parse_parameters(ParameterHandler &prm)
    {
      regions.clear();
      prm.enter_subsection("Materials");
      for (auto &slot : slots)
        {
          const std::string name = "Region " + std::to_string(slot->id);
          const std::string path = "Materials/" + name;
          check_input(slot->thickness > 0.,
                      path + "/Thickness",
                      "must be positive, got "
                        + std::to_string(slot->thickness));
          prm.enter_subsection(name);
          RegionMaterial m;
          m.law_name  = slot->law;
          m.thickness = slot->thickness;
          m.density   = slot->density;
          m.law       = LawRegistry::instance().take(
            slot->laws, prm, slot->law, path + "/Law", path);
          prm.leave_subsection();

          // The material frame.
          if (Utilities::trim(slot->warp_direction) == "gmsh")
            m.warp_from_mesh = true;
          else if (!Utilities::trim(slot->warp_direction).empty())
            {
              const auto parts =
                Utilities::split_string_list(slot->warp_direction, ',');
              bool numbers = parts.size() == 3;
              for (unsigned int d = 0; numbers && d < 3; ++d)
                try
                  {
                    m.warp_direction[d] = Utilities::string_to_double(parts[d]);
                  }
                catch (...)
                  {
                    numbers = false;
                  }
              check_input(numbers && m.warp_direction.norm() > 0.,
                          path + "/Warp direction",
                          "must be a non-zero vector 'x, y, z', got '"
                            + slot->warp_direction + "'");
            }
          check_input(m.law->isotropic() || m.warp_direction.norm() > 0.
                        || m.warp_from_mesh,
                      path + "/Warp direction",
                      "the law '" + slot->law
                        + "' is anisotropic and needs the direction of its "
                          "first material axis");

          // Prestress: n or n1, n2 [N/m].
          {
            const auto parts =
              Utilities::split_string_list(slot->prestress, ',');
            std::vector<double> n;
            try
              {
                for (const auto &part : parts)
                  n.push_back(Utilities::string_to_double(part));
              }
            catch (...)
              {
                n.clear();
              }
            check_input((n.size() == 1 || n.size() == 2)
                          && std::isfinite(n.front())
                          && std::isfinite(n.back()),
                        path + "/Prestress",
                        "must be 'n' or 'n1, n2' in N/m, got '"
                          + slot->prestress + "'");
            check_input(n.front() == n.back() || m.warp_direction.norm() > 0.
                          || m.warp_from_mesh,
                        path + "/Prestress",
                        "unequal warp and fill prestress needs the region's "
                        "Warp direction");
            m.prestress = {{n.front(), n.back()}};
            if (n.front() != 0. || n.back() != 0.)
              {
                SymmetricTensor<2, 2> S0;
                S0[0][0] = n.front() / slot->thickness;
                S0[1][1] = n.back() / slot->thickness;
                m.law    = std::make_shared<PrestressedLaw>(m.law, S0);
              }
          }

          m.plain_law = m.law;
          if (slot->wrinkling)
            {
              check_input(slot->residual_stiffness < 1e-2,
                          path + "/Wrinkling residual stiffness",
                          "must be below 1e-2 (a fraction of the law kept "
                          "in compression), got "
                            + std::to_string(slot->residual_stiffness));
              auto relaxed =
                std::make_shared<TensionFieldLaw>(m.law,
                                                  slot->residual_stiffness,
                                                  slot->smoothing);
              m.tension_field = relaxed;
              m.law           = relaxed;
            }
          if (slot->bending)
            {
              check_input(std::isfinite(slot->bending_factor)
                            && slot->bending_factor > 0.,
                          path + "/Bending stiffness factor",
                          "must be positive, got "
                            + std::to_string(slot->bending_factor));
              m.bending_factor = slot->bending_factor;
            }
          m.membrane_strains = slot->membrane_strains;
          regions[slot->id]  = m;
        }
      prm.leave_subsection();
    }

    const RegionMaterial &
    MaterialRegions::operator[](const types::material_id id) const
    {
      const auto it = regions.find(id);
      if (it != regions.end())
        return it->second;
      // (The message only when it is needed: this runs for every cell.)
      throw InputError(
        "Materials/Region " + std::to_string(id),
        "the mesh has cells with material id " + std::to_string(id)
          + " but the input has no such subsection (regions given: " +
          [this]() {
            std::string s;
            for (const auto &[i, m] : regions)
              s += (s.empty() ? "" : ", ") + std::to_string(i);
            return s;
          }()
          + ")");
    }

    bool
    MaterialRegions::any_wrinkling() const
    {
      for (const auto &[id, m] : regions)
        if (m.tension_field)
          return true;
      return false;
    }

    bool
    MaterialRegions::any_bending() const
    {
      for (const auto &[id, m] : regions)
        if (m.bending_factor > 0.)
          return true;
      return false;
    }

    std::vector<types::material_id>
    MaterialRegions::ids() const
    {
      std::vector<types::material_id> result;
      for (const auto &[id, m] : regions)
        result.push_back(id);
      return result;
    }
  } // namespace membrane
} // namespace pneuma
