# Sourced by the scripts: OpenMPI refuses to run as root (CI does) unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# No grace period before mpirun cleans up a job whose rank exited non-zero
# (by default 1 s twice, on every bad-input case run on 2 ranks).
# tests/CMakeLists.txt gives the tests the same environment.
export OMPI_MCA_odls_base_sigkill_timeout=0
