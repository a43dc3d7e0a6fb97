# OpenSubdiv's CPU library (osdCPU) as the imported target OpenSubdivCPU::osdCPU.
#
# Debian's own OpenSubdiv CMake package references an osdCPU_static target it does not ship, so the header and
# the library are located directly. Installed with GradientShadows' package, whose content library needs it.
find_path(OpenSubdivCPU_INCLUDE_DIR opensubdiv/version.h)
find_library(OpenSubdivCPU_LIBRARY osdCPU)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenSubdivCPU REQUIRED_VARS OpenSubdivCPU_LIBRARY OpenSubdivCPU_INCLUDE_DIR)
if(OpenSubdivCPU_FOUND AND NOT TARGET OpenSubdivCPU::osdCPU)
  add_library(OpenSubdivCPU::osdCPU UNKNOWN IMPORTED)
  set_target_properties(OpenSubdivCPU::osdCPU PROPERTIES
    IMPORTED_LOCATION ${OpenSubdivCPU_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${OpenSubdivCPU_INCLUDE_DIR})
endif()
mark_as_advanced(OpenSubdivCPU_INCLUDE_DIR OpenSubdivCPU_LIBRARY)
