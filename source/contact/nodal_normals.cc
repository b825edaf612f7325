#include <deal.II/base/config.h>
#include <deal.II/base/exceptions.h>

#include <pneuma/contact/nodal_normals.h>

#include <Sacado.hpp>

#include <cmath>

namespace pneuma
{
  namespace contact
  {
    namespace
    {
      /// d l_i / dt at t = k / degree of the 1D Lagrange basis on i/degree.
      double
      lagrange_derivative(const unsigned int degree,
                          const unsigned int i,
                          const unsigned int k)
      {
        if (degree == 1)
          return i == 0 ? -1. : 1.;
        const double t = 0.5 * k;
        switch (i)
          {
            case 0:
              return 4. * t - 3.;
            case 1:
              return -8. * t + 4.;
            default:
              return 4. * t - 1.;
          }
      }

      /// nbar from the dependency node positions y.
      template <typename Number, typename Incidences>
      void
      average(const Incidences                         &cells,
              const std::vector<std::array<Number, 3>> &y,
              Number                                    n[3])
      {
        using std::sqrt;
        Number S[3] = {0., 0., 0.};
        for (const auto &e : cells)
          {
            Number t1[3] = {0., 0., 0.}, t2[3] = {0., 0., 0.};
            for (unsigned int k = 0; k < e.line1.size(); ++k)
              for (unsigned int c = 0; c < 3; ++c)
                t1[c] += e.weight1[k] * y[e.line1[k]][c];
            for (unsigned int k = 0; k < e.line2.size(); ++k)
              for (unsigned int c = 0; c < 3; ++c)
                t2[c] += e.weight2[k] * y[e.line2[k]][c];
            const Number m[3]   = {t1[1] * t2[2] - t1[2] * t2[1],
                                   t1[2] * t2[0] - t1[0] * t2[2],
                                   t1[0] * t2[1] - t1[1] * t2[0]};
            const Number length = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
            for (unsigned int c = 0; c < 3; ++c)
              S[c] += e.sign * m[c] / length;
          }
        const Number length = sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2]);
        for (unsigned int c = 0; c < 3; ++c)
          n[c] = S[c] / length;
      }
    } // namespace

    void
    NodalNormals::reinit(const unsigned int             degree,
                         const std::vector<NormalCell> &cells)
    {
      nodes.clear();
      const unsigned int p = degree, k = degree + 1;
      for (const auto &cell : cells)
        for (unsigned int j0 = 0; j0 < k; ++j0)
          for (unsigned int i0 = 0; i0 < k; ++i0)
            {
              Node &node = nodes[cell.dofs[3 * (i0 + k * j0)]];
              // Index of a lattice node of this cell among the node's
              // dependencies (added if new).
              const auto index = [&](const unsigned int a) {
                for (unsigned int d = 0; d < node.reference.size(); ++d)
                  if (node.dofs[3 * d] == cell.dofs[3 * a])
                    return d;
                for (unsigned int c = 0; c < 3; ++c)
                  node.dofs.push_back(cell.dofs[3 * a + c]);
                node.reference.push_back(cell.reference[a]);
                return static_cast<unsigned int>(node.reference.size() - 1);
              };
              index(i0 + k * j0); // the node itself comes first
              Node::Incidence e;
              e.sign = cell.sign;
              for (unsigned int i = 0; i <= p; ++i)
                {
                  e.line1.push_back(index(i + k * j0));
                  e.weight1.push_back(lagrange_derivative(p, i, i0));
                }
              for (unsigned int j = 0; j <= p; ++j)
                {
                  e.line2.push_back(index(i0 + k * j));
                  e.weight2.push_back(lagrange_derivative(p, j, j0));
                }
              node.cells.push_back(e);
            }
    }

    void
    NodalNormals::clear_cache()
    {
      for (auto &[key, node] : nodes)
        node.have_normal = node.have_jacobian = false;
    }

    NodalNormals::Node &
    NodalNormals::find(const types::global_dof_index key)
    {
      const auto it = nodes.find(key);
      Assert(it != nodes.end(), ExcInternalError());
      return it->second;
    }

    const NodalNormals::Node &
    NodalNormals::find(const types::global_dof_index key) const
    {
      const auto it = nodes.find(key);
      Assert(it != nodes.end(), ExcInternalError());
      return it->second;
    }

    const std::vector<types::global_dof_index> &
    NodalNormals::dependencies(const types::global_dof_index key) const
    {
      return find(key).dofs;
    }

    const Tensor<1, 3> &
    NodalNormals::normal(const types::global_dof_index key, const LA::Vector &u)
    {
      Node &node = find(key);
      if (!node.have_normal)
        {
          std::vector<std::array<double, 3>> y(node.reference.size());
          for (unsigned int d = 0; d < y.size(); ++d)
            for (unsigned int c = 0; c < 3; ++c)
              y[d][c] = node.reference[d][c] + u[node.dofs[3 * d + c]];
          double n[3];
          average(node.cells, y, n);
          for (unsigned int c = 0; c < 3; ++c)
            node.value[c] = n[c];
          node.have_normal = true;
        }
      return node.value;
    }

    const FullMatrix<double> &
    NodalNormals::jacobian(const types::global_dof_index key,
                           const LA::Vector             &u)
    {
      Node &node = find(key);
      if (!node.have_jacobian)
        {
          using AD                         = Sacado::Fad::DFad<double>;
          const unsigned int             n = node.dofs.size();
          std::vector<std::array<AD, 3>> y(node.reference.size());
          for (unsigned int d = 0; d < y.size(); ++d)
            for (unsigned int c = 0; c < 3; ++c)
              y[d][c] = AD(n,
                           3 * d + c,
                           node.reference[d][c] + u[node.dofs[3 * d + c]]);
          AD nbar[3];
          average(node.cells, y, nbar);
          node.jacobian.reinit(3, n);
          for (unsigned int c = 0; c < 3; ++c)
            {
              node.value[c] = nbar[c].val();
              for (unsigned int j = 0; j < n; ++j)
                node.jacobian(c, j) = nbar[c].dx(j);
            }
          node.have_normal = node.have_jacobian = true;
        }
      return node.jacobian;
    }

  } // namespace contact
} // namespace pneuma
