#include <pneuma/core/mpi_start.h>

#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <system_error>
#include <vector>

namespace pneuma
{
  namespace
  {
    bool
    started_by_launcher()
    {
      // A launcher leaves one of these; a singleton has none.
      for (const char *launched : {"OMPI_COMM_WORLD_SIZE",
                                   "OMPI_UNIVERSE_SIZE",
                                   "PMIX_RANK",
                                   "PMI_RANK",
                                   "PMI_SIZE",
                                   "SLURM_PROCID"})
        if (std::getenv(launched) != nullptr)
          return true;
      return false;
    }

    /// A fresh directory of this process only, or "" if none could be made
    /// (then Open MPI's default stays).
    std::string
    make_private_session_base()
    {
      const char *tmp  = std::getenv("TMPDIR");
      std::string path = (tmp != nullptr && *tmp != '\0') ? tmp : "/tmp";
      path += "/pneuma-mpi-XXXXXX";
      std::vector<char> name(path.begin(), path.end());
      name.push_back('\0');
      if (mkdtemp(name.data()) == nullptr)
        return "";
      return name.data();
    }
  } // namespace

  MpiStart::MpiStart()
  {
    if (started_by_launcher())
      return;
    // setenv with overwrite = 0: the user's own settings stay.
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    setenv("OMPI_MCA_pml", "ob1", 0);
    setenv("OMPI_MCA_btl", "self", 0);
    setenv("OMPI_MCA_sharedfp", "^sm", 0);
    if (std::getenv("OMPI_MCA_orte_tmpdir_base") == nullptr)
      {
        session_base = make_private_session_base();
        if (!session_base.empty())
          setenv("OMPI_MCA_orte_tmpdir_base", session_base.c_str(), 1);
      }
  }

  MpiStart::~MpiStart()
  {
    if (session_base.empty())
      return;
    std::error_code ignored;
    std::filesystem::remove_all(session_base, ignored);
  }
} // namespace pneuma
