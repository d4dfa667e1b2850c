# CHOLMOD from SuiteSparse 5.12 (Debian libsuitesparse-dev), which has no CMake
# config. Provides CHOLMOD::CHOLMOD for Eigen's CholmodSupport module.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY NAMES cholmod)
find_library(SUITESPARSE_CONFIG_LIBRARY NAMES suitesparseconfig)
# The BLAS that CHOLMOD itself links (libblas.so.3: OpenBLAS's pthread build,
# installed by setup.sh). Ceres's link interface names ATLAS's libf77blas,
# which the dynamic linker would otherwise search first, so the supernodal
# kernels (dgemm, dsyrk, dtrsm) would run single-threaded in ATLAS.
find_library(CHOLMOD_BLAS_LIBRARY NAMES blas)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CHOLMOD
  REQUIRED_VARS CHOLMOD_LIBRARY SUITESPARSE_CONFIG_LIBRARY CHOLMOD_INCLUDE_DIR)
if(CHOLMOD_FOUND AND NOT TARGET CHOLMOD::CHOLMOD)
  add_library(CHOLMOD::CHOLMOD UNKNOWN IMPORTED)
  set_target_properties(CHOLMOD::CHOLMOD PROPERTIES
    IMPORTED_LOCATION "${CHOLMOD_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${SUITESPARSE_CONFIG_LIBRARY}")
  if(CHOLMOD_BLAS_LIBRARY)
    # Named before every library on the link line, so it comes first in the
    # program's search order.
    set_target_properties(CHOLMOD::CHOLMOD PROPERTIES INTERFACE_LINK_OPTIONS
      "SHELL:-Wl,--push-state,--no-as-needed ${CHOLMOD_BLAS_LIBRARY} -Wl,--pop-state")
  endif()
endif()
