/**
 * @file
 * The element "solid beam": the source paper's solid-beam element (its
 * section 3.1, after Konyukhov & Schweizerhof; doc/theory.md §8.2). Per
 * node the displacement of the mid-line (components 0-2) and the changes
 * of the two semi-axis vectors a1, a2 of the elliptic section (3-5, 6-8);
 * the hyperelastic energy of the 3D continuum over the section
 * (SolidBeamSection, St. Venant-Kirchhoff or compressible neo-Hookean)
 * chained with the linear shape functions (SolidBeamElement), at one Gauss
 * point per cell against transverse shear locking. The reference section:
 * \f$A_1 = a\,e_1\f$ with \f$e_1\f$ the Section axis (or the shape's
 * outward radial direction for a ring or helix) projected normal to the
 * node tangent t, and \f$A_2 = b\,t\times e_1\f$. It carries a
 * conservative end moment (SolidBeamElement::end_moment_terms).
 */

#include <deal.II/base/quadrature_lib.h>

#include <pneuma/cables/cable_element.h>
#include <pneuma/cables/cable_parameters.h>
#include <pneuma/cables/solid_beam_element.h>
#include <pneuma/cables/solid_beam_section.h>
#include <pneuma/core/input_error.h>
#include <pneuma/loads/loads.h>

#include <array>
#include <cmath>
#include <memory>

namespace pneuma
{
  namespace cables
  {
    namespace
    {
      class SolidBeam : public CableElement
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Law",
                            law,
                            "3D hyperelastic law of the section continuum "
                            "(compressible neo-Hookean).",
                            Patterns::Selection(
                              "Saint Venant-Kirchhoff|neo-Hookean"));
          prm.add_parameter("Poisson's ratio",
                            poisson_ratio,
                            "nu, in (-1, 0.5) (the law is compressible).",
                            Patterns::Double(-1., 0.5));
          prm.add_parameter("Section axis",
                            section_axis_text,
                            "Direction of the semi-axis a, projected normal "
                            "to the mid-line; for a ring or helix the "
                            "outward radial direction is used.",
                            Patterns::Anything());
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_input(poisson_ratio > -1. && poisson_ratio < 0.5,
                      path + "/Poisson's ratio",
                      "must lie in (-1, 0.5) (the solid-beam law is "
                      "compressible)");
          section_axis = Tensor<1, 3>(
            loads::parse_point(section_axis_text, path + "/Section axis"));
          this->path = path;
        }

        unsigned int
        n_components() const override
        {
          return 9;
        }

        std::vector<std::string>
        component_names() const override
        {
          std::vector<std::string> names(3, "displacement");
          names.insert(names.end(), 3, "section_axis_1_change");
          names.insert(names.end(), 3, "section_axis_2_change");
          return names;
        }

        std::vector<std::string>
        output_names() const override
        {
          return SolidBeamElement::output_names();
        }

        Quadrature<1>
        quadrature() const override
        {
          return QGauss<1>(1);
        }

        /// a1 in components 3-5, a2 in 6-8.
        std::vector<unsigned int>
        section_vector_components() const override
        {
          return {3, 4, 5, 6, 7, 8};
        }

        bool
        carries_moments() const override
        {
          return true;
        }

        void
        setup(const CableDefinition &cable, const double length_ratio) override
        {
          element = std::make_unique<SolidBeamElement>(
            BeamMaterial{law == "neo-Hookean" ? BeamLaw::neo_hookean
                                              : BeamLaw::saint_venant_kirchhoff,
                         cable.youngs_modulus,
                         poisson_ratio},
            length_ratio);
          semi_axes     = {{cable.section_a, cable.section_b}};
          moment_axes   = {};
          moment_angles = {{0., 0.}};
        }

        void
        set_length_ratio(const double length_ratio) override
        {
          element->set_length_ratio(length_ratio);
        }

        void
        reference_values(const CableNode  &node,
                         ArrayView<double> values) const override
        {
          const Tensor<1, 3> &t  = node.tangent;
          Tensor<1, 3>        e1 = node.section_direction.norm() > 0.
                                     ? node.section_direction
                                     : section_axis;
          check_input(e1.norm() > 0.,
                      path + "/Section axis",
                      "must not be zero");
          e1 -= (e1 * t) * t;
          check_input(e1.norm() > 1e-8,
                      path + "/Section axis",
                      "is parallel to the cable at a node");
          e1 /= e1.norm();
          const Tensor<1, 3> e2 = cross_product_3d(t, e1);
          for (unsigned int c = 0; c < 3; ++c)
            {
              values[3 + c] = semi_axes[0] * e1[c];
              values[6 + c] = semi_axes[1] * e2[c];
            }
        }

        void
        cell_terms(const FEValues<1, 3> &fe_values,
                   const Tensor<1, 3>   &tangent,
                   const Vector<double> &local_reference,
                   const Vector<double> &local_u,
                   FullMatrix<double>   *cell_matrix,
                   Vector<double>       *cell_residual,
                   CableCellOutput      *output) const override
        {
          if (output)
            output->values.resize(6);
          element->cell_terms(fe_values,
                              tangent,
                              local_reference,
                              local_u,
                              cell_matrix,
                              cell_residual,
                              output ? &output->values : nullptr);
          if (output)
            {
              const auto &v          = output->values;
              output->axial_force    = v[0];
              output->bending_moment = std::hypot(v[1], v[2]);
              output->torsion_moment = std::abs(v[3]);
            }
        }

        void
        end_moment_terms(const Tensor<1, 3>   &moment,
                         const Vector<double> &node_reference,
                         const Vector<double> &node_u,
                         FullMatrix<double>   *node_matrix,
                         Vector<double>       *node_residual) const override
        {
          std::array<Tensor<1, 3>, 2> A, a;
          section(node_reference, node_u, A, a);
          SolidBeamElement::end_moment_terms(moment,
                                             A,
                                             a,
                                             moment_axes,
                                             moment_angles,
                                             node_matrix,
                                             node_residual,
                                             nullptr);
        }

        double
        commit_end_moment(const Tensor<1, 3>   &moment,
                          const Vector<double> &node_reference,
                          const Vector<double> &node_u) override
        {
          std::array<Tensor<1, 3>, 2> A, a;
          section(node_reference, node_u, A, a);
          std::array<double, 2> theta{{0., 0.}};
          SolidBeamElement::end_moment_terms(
            moment, A, a, moment_axes, moment_angles, nullptr, nullptr, &theta);
          moment_axes   = a;
          moment_angles = theta;
          return SolidBeamElement::section_rotation(moment, A, theta);
        }

        std::vector<double>
        committed_state() const override
        {
          std::vector<double> s;
          for (unsigned int k = 0; k < 2; ++k)
            {
              for (unsigned int c = 0; c < 3; ++c)
                s.push_back(moment_axes[k][c]);
              s.push_back(moment_angles[k]);
            }
          return s;
        }

        void
        restore_state(const std::vector<double> &s) override
        {
          AssertThrow(s.size() == 8, ExcInternalError());
          for (unsigned int k = 0; k < 2; ++k)
            {
              for (unsigned int c = 0; c < 3; ++c)
                moment_axes[k][c] = s[4 * k + c];
              moment_angles[k] = s[4 * k + 3];
            }
        }

      private:
        /// Reference (A) and current (a) semi-axis vectors of a node.
        static void
        section(const Vector<double>        &node_reference,
                const Vector<double>        &node_u,
                std::array<Tensor<1, 3>, 2> &A,
                std::array<Tensor<1, 3>, 2> &a)
        {
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int c = 0; c < 3; ++c)
              {
                A[k][c] = node_reference[3 + 3 * k + c];
                a[k][c] = A[k][c] + node_u[3 + 3 * k + c];
              }
        }

        // Constants (bound).
        std::string law               = "Saint Venant-Kirchhoff";
        double      poisson_ratio     = 0.3;
        std::string section_axis_text = "0, 0, 1";

        /// "Cables/Cable <k>/solid beam", for messages.
        std::string                       path;
        Tensor<1, 3>                      section_axis;
        std::array<double, 2>             semi_axes{{0., 0.}};
        std::unique_ptr<SolidBeamElement> element;
        /// End-moment tracking: the end semi-axis vectors and their angles
        /// about the moment axis at the last converged step.
        std::array<Tensor<1, 3>, 2> moment_axes;
        std::array<double, 2>       moment_angles{{0., 0.}};
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(CableElement,
                            SolidBeam,
                            "solid beam",
                            "the source paper's solid-beam element (mid-line "
                            "and two section axes per node, 3D material over "
                            "the elliptic section)")
  } // namespace cables
} // namespace pneuma
