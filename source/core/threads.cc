#include <deal.II/base/multithread_info.h>

#include <pneuma/core/threads.h>

#include <dlfcn.h>
#include <sched.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace pneuma
{
  unsigned int
  set_thread_counts(const MPI_Comm comm)
  {
    // Ranks sharing this node.
    MPI_Comm node;
    MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    int node_ranks = 1;
    MPI_Comm_size(node, &node_ranks);
    MPI_Comm_free(&node);

    // Cores: those of the node shared by its ranks, and no more than this
    // process is bound to (mpirun may bind each rank to one core).
    unsigned int cores = std::max(1u, std::thread::hardware_concurrency());
    cpu_set_t    set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) == 0)
      cores = std::min<unsigned int>(cores, std::max(1, CPU_COUNT(&set)));
    const unsigned int per_rank =
      std::max(1u,
               std::min(cores,
                        std::max(1u, std::thread::hardware_concurrency())
                          / static_cast<unsigned int>(node_ranks)));

    const bool user_set = std::getenv("OPENBLAS_NUM_THREADS") != nullptr
                          || std::getenv("OMP_NUM_THREADS") != nullptr;
    using SetThreads    = void (*)(int);
    using GetThreads    = int (*)();
    const auto set_blas = reinterpret_cast<SetThreads>(
      dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    const auto get_blas = reinterpret_cast<GetThreads>(
      dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    if (!user_set && set_blas)
      set_blas(static_cast<int>(per_rank));
    // deal.II's task threads (the cell loops of the assembly): as many;
    // DEAL_II_NUM_THREADS lowers it.
    dealii::MultithreadInfo::set_thread_limit(per_rank);
    return get_blas ? static_cast<unsigned int>(std::max(1, get_blas())) : 0;
  }
} // namespace pneuma
