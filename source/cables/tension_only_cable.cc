#include <deal.II/base/symmetric_tensor.h>

#include <pneuma/cables/tension_only_cable.h>

namespace pneuma
{
  namespace cables
  {
    TensionOnlyCable::TensionOnlyCable(const double axial_stiffness,
                                       const double length_ratio,
                                       const double slack_ratio)
      : EA(axial_stiffness)
      , rho(length_ratio)
      , slack(slack_ratio)
    {
    }

    CablePoint
    TensionOnlyCable::evaluate(const Tensor<1, 3> &dx_dS) const
    {
      CablePoint         p;
      const double       l  = dx_dS.norm();
      const Tensor<1, 3> e  = dx_dS / l;
      p.stretch             = rho * l;
      const double EA_eff   = p.stretch >= 1. ? EA : slack * EA;
      p.force               = EA_eff * (p.stretch - 1.);
      p.force_vector        = p.force * e;
      const Tensor<2, 3> ee = outer_product(e, e);
      p.tangent =
        EA_eff * rho * ee
        + (p.force / l) * (Tensor<2, 3>(unit_symmetric_tensor<3>()) - ee);
      return p;
    }
  } // namespace cables
} // namespace pneuma
