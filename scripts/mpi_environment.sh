# Sourced by the scripts: OpenMPI refuses to run as root (CI does) unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# The scripts run on one machine: shared-memory transport only (what Open
# MPI picks there anyway, without first loading libfabric and PSM), and no
# grace period before mpirun cleans up a job whose rank exited non-zero
# (by default 1 s twice, on every bad-input case run on 2 ranks).
# tests/CMakeLists.txt gives the tests the same environment.
export OMPI_MCA_pml=ob1
export OMPI_MCA_btl=self,vader
export OMPI_MCA_odls_base_sigkill_timeout=0
