#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/fe/fe_values.h>

#include <pneuma/membrane/face_assembly.h>

#include <memory>

namespace pneuma
{
  namespace membrane
  {
    namespace
    {
      /// Does @p cell visit interior face @p f (see MeshEdge)?
      bool
      visits(const DoFHandler<2, 3>::active_cell_iterator &cell,
             const unsigned int                            f)
      {
        if (cell->has_periodic_neighbor(f))
          return false;
        const auto neighbor = cell->neighbor(f);
        // A finer neighbor visits the edge (its subface).
        if (neighbor->has_children())
          return false;
        // A coarser neighbor: this, the finer side, visits it.
        if (cell->neighbor_is_coarser(f))
          return true;
        if (neighbor->is_locally_owned())
          return cell->id() < neighbor->id();
        return cell->subdomain_id() < neighbor->subdomain_id();
      }

      /// One thread's working memory.
      struct Scratch
      {
        Scratch(const Mapping<2, 3>            &mapping,
                const FiniteElement<2, 3>      &fe,
                const Quadrature<1>            &quadrature,
                const UpdateFlags               flags,
                const std::vector<FaceTerms *> &terms)
          : interface(mapping, fe, quadrature, flags)
          , face(mapping, fe, quadrature, flags)
          , terms(&terms)
        {
          for (const auto *t : terms)
            scratch.push_back(t->new_scratch());
        }
        Scratch(const Scratch &other)
          : Scratch(other.face.get_mapping(),
                    other.face.get_fe(),
                    other.face.get_quadrature(),
                    other.face.get_update_flags(),
                    *other.terms)
        {
        }
        FEInterfaceValues<2, 3>                          interface;
        FEFaceValues<2, 3>                               face;
        const std::vector<FaceTerms *>                  *terms;
        std::vector<std::unique_ptr<FaceTerms::Scratch>> scratch;
      };

      /// What a face hands to the copier.
      struct Copy
      {
        explicit Copy(const std::vector<FaceTerms *> &terms)
          : terms(&terms)
        {
          for (const auto *t : terms)
            records.push_back(t->new_record());
        }
        Copy(const Copy &other)
          : Copy(*other.terms)
        {
        }
        Copy &
        operator=(const Copy &other)
        {
          if (this != &other)
            {
              dofs     = other.dofs;
              matrix   = other.matrix;
              residual = other.residual;
              terms    = other.terms;
              records.clear();
              for (const auto *t : *terms)
                records.push_back(t->new_record());
            }
          return *this;
        }
        std::vector<types::global_dof_index>            dofs;
        FullMatrix<double>                              matrix;
        Vector<double>                                  residual;
        const std::vector<FaceTerms *>                 *terms;
        std::vector<std::unique_ptr<FaceTerms::Record>> records;
      };
    } // namespace

    std::vector<MeshEdge>
    mesh_edges(const DoFHandler<2, 3> &dofs,
               const bool              interior,
               const bool              boundary)
    {
      std::vector<MeshEdge> edges;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            {
              if (cell->at_boundary(f) && !cell->has_periodic_neighbor(f))
                {
                  if (boundary)
                    edges.push_back({cell, f, false});
                }
              else if (interior && visits(cell, f))
                edges.push_back({cell, f, true});
            }
      return edges;
    }

    void
    add_face_sparsity(const DoFHandler<2, 3>          &dofs,
                      const AffineConstraints<double> &constraints,
                      DynamicSparsityPattern          &dsp)
    {
      const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
      std::vector<types::global_dof_index> joint(2 * n);
      for (const auto &e : mesh_edges(dofs, true, false))
        {
          const auto neighbor = e.cell->neighbor(e.face);
          std::vector<types::global_dof_index> mine(n), theirs(n);
          e.cell->get_dof_indices(mine);
          neighbor->get_dof_indices(theirs);
          std::copy(mine.begin(), mine.end(), joint.begin());
          std::copy(theirs.begin(), theirs.end(), joint.begin() + n);
          constraints.add_entries_local_to_global(joint, dsp, false);
        }
    }

    void
    assemble_faces(const Mapping<2, 3>             &mapping,
                   const DoFHandler<2, 3>          &dofs,
                   const std::vector<FaceTerms *>  &terms,
                   const LA::Vector                &u,
                   const AffineConstraints<double> &constraints,
                   LA::SparseMatrix                *tangent,
                   LA::Vector                      *residual)
    {
      unsigned int n_q      = 1;
      UpdateFlags  flags    = update_default;
      bool         interior = false, boundary = false;
      for (const auto *t : terms)
        {
          n_q = std::max(n_q, t->n_quadrature_points());
          flags |= t->update_flags();
          interior |= t->on_interior_faces();
          boundary |= t->on_boundary_faces();
        }
      const auto      edges = mesh_edges(dofs, interior, boundary);
      const QGauss<1> quadrature(n_q);
      const auto worker = [&](const std::vector<MeshEdge>::const_iterator &e,
                              Scratch &scratch,
                              Copy    &copy) {
        FullMatrix<double> *matrix = tangent ? &copy.matrix : nullptr;
        Vector<double>     *vector = residual ? &copy.residual : nullptr;
        if (e->interior)
          {
            auto      &fiv      = scratch.interface;
            const auto neighbor = e->cell->neighbor(e->face);
            // The finer side visits the edge: the coarser neighbor's
            // face and subface.
            const auto [face, subface] =
              e->cell->neighbor_is_coarser(e->face)
                ? e->cell->neighbor_of_coarser_neighbor(e->face)
                : std::make_pair(e->cell->neighbor_face_no(e->face),
                                 numbers::invalid_unsigned_int);
            fiv.reinit(e->cell,
                       e->face,
                       numbers::invalid_unsigned_int,
                       neighbor,
                       face,
                       subface);
            copy.dofs = fiv.get_interface_dof_indices();
          }
        else
          {
            scratch.face.reinit(e->cell, e->face);
            copy.dofs.resize(dofs.get_fe().n_dofs_per_cell());
            e->cell->get_dof_indices(copy.dofs);
          }
        const unsigned int  n = copy.dofs.size();
        std::vector<double> local_u(n);
        for (unsigned int i = 0; i < n; ++i)
          local_u[i] = u[copy.dofs[i]];
        copy.matrix.reinit(n, n);
        copy.residual.reinit(n);
        for (unsigned int k = 0; k < terms.size(); ++k)
          if (e->interior && terms[k]->on_interior_faces())
            terms[k]->interior_face(scratch.interface,
                                    local_u,
                                    matrix,
                                    vector,
                                    *scratch.scratch[k],
                                    *copy.records[k]);
          else if (!e->interior && terms[k]->on_boundary_faces())
            terms[k]->boundary_face(e->cell,
                                    e->face,
                                    scratch.face,
                                    local_u,
                                    matrix,
                                    vector,
                                    *scratch.scratch[k],
                                    *copy.records[k]);
      };
      const auto copier = [&](const Copy &copy) {
        for (unsigned int k = 0; k < terms.size(); ++k)
          terms[k]->commit(*copy.records[k]);
        if (tangent && residual)
          constraints.distribute_local_to_global(
            copy.matrix, copy.residual, copy.dofs, *tangent, *residual);
        else if (tangent)
          constraints.distribute_local_to_global(copy.matrix,
                                                 copy.dofs,
                                                 *tangent);
        else if (residual)
          constraints.distribute_local_to_global(copy.residual,
                                                 copy.dofs,
                                                 *residual);
      };
      WorkStream::run(edges.cbegin(),
                      edges.cend(),
                      worker,
                      copier,
                      Scratch(mapping, dofs.get_fe(), quadrature, flags, terms),
                      Copy(terms));
    }
  } // namespace membrane
} // namespace pneuma
