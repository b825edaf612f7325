#include <deal.II/lac/exceptions.h>

#include <pneuma/core/local_access.h>

#include <Epetra_FEVector.h>

#include <algorithm>

namespace pneuma
{
  namespace LA
  {
    OwnedValues::OwnedValues(Vector &v)
    {
      if (v.has_ghost_elements())
        return;
      Epetra_FEVector       &e   = v.trilinos_vector();
      const Epetra_BlockMap &map = e.Map();
      if (!map.LinearMap() || map.NumMyElements() == 0)
        return;
      values = e[0];
      first  = map.MinMyGID64();
      n      = map.NumMyElements();
    }

    bool
    VectorSnapshot::matches(const Vector &u) const
    {
      const Epetra_MultiVector &e = u.trilinos_vector();
      return map && map->PointSameAs(e.Map())
             && values.size() == std::size_t(e.MyLength())
             && std::equal(values.begin(), values.end(), e[0]);
    }

    void
    VectorSnapshot::take(const Vector &u)
    {
      const Epetra_MultiVector &e = u.trilinos_vector();
      map                         = std::make_unique<Epetra_BlockMap>(e.Map());
      values.assign(e[0], e[0] + e.MyLength());
    }

    const double *
    GhostedIndices::values(const Vector                          &u,
                           const dealii::types::global_dof_index *dofs,
                           const unsigned int                     cells,
                           const unsigned int                     n_dofs)
    {
      const Epetra_MultiVector &e    = u.trilinos_vector();
      const Epetra_BlockMap    &umap = e.Map();
      if (!map || !map->PointSameAs(umap) || dofs != dofs_address
          || cells != n_cells || n_dofs != n_dofs_per_cell)
        {
          map             = std::make_unique<Epetra_BlockMap>(umap);
          dofs_address    = dofs;
          n_cells         = cells;
          n_dofs_per_cell = n_dofs;
          local.resize(std::size_t(cells) * n_dofs);
          complete = true;
          for (std::size_t k = 0; k < local.size(); ++k)
            {
              local[k] =
                umap.LID(static_cast<dealii::TrilinosWrappers::types::int_type>(
                  dofs[k]));
              complete = complete && local[k] >= 0;
            }
        }
      return complete ? e[0] : nullptr;
    }

    void
    GhostImport::operator()(const Vector &owned, Vector &ghosted)
    {
      const Epetra_BlockMap &source = owned.trilinos_vector().Map();
      Epetra_FEVector       &target = ghosted.trilinos_vector();
      if (!import || !import->SourceMap().SameBlockMapDataAs(source)
          || !import->TargetMap().SameBlockMapDataAs(target.Map()))
        import = std::make_unique<Epetra_Import>(target.Map(), source);
      const int error = target.Import(owned.trilinos_vector(), *import, Insert);
      AssertThrow(error == 0, dealii::LACExceptions::ExcTrilinosError(error));
    }
  } // namespace LA
} // namespace pneuma
