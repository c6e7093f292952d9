# The version check for cantools_odConfig.cmake beside it: the one of the Python package's CMake package.
include("${CMAKE_CURRENT_LIST_DIR}/cantools_odLocate.cmake")
if(_cantools_od_package_dir)
  include("${_cantools_od_package_dir}/cantools_odConfigVersion.cmake")
else()
  set(PACKAGE_VERSION "unknown")
  set(PACKAGE_VERSION_UNSUITABLE TRUE)
endif()
