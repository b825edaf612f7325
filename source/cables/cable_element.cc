#include <deal.II/base/exceptions.h>

#include <pneuma/cables/cable_element.h>

namespace pneuma
{
  namespace cables
  {
    void
    CableElement::reference_values(const CableNode &, ArrayView<double>) const
    {
    }

    void
    CableElement::end_moment_terms(const Tensor<1, 3> &,
                                   const Vector<double> &,
                                   const Vector<double> &,
                                   FullMatrix<double> *,
                                   Vector<double> *) const
    {
      // CableParameters rejects an End moment on such an element.
      AssertThrow(carries_moments(),
                  ExcMessage("this cable element carries no moment"));
      AssertThrow(false, ExcNotImplemented());
    }

    double
    CableElement::commit_end_moment(const Tensor<1, 3> &,
                                    const Vector<double> &,
                                    const Vector<double> &)
    {
      AssertThrow(carries_moments(),
                  ExcMessage("this cable element carries no moment"));
      AssertThrow(false, ExcNotImplemented());
      return 0.;
    }
  } // namespace cables
} // namespace pneuma
