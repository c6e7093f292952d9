# find_package(cantools_od CONFIG) finds this file where pip installs it, in
# <prefix>/share/cmake/cantools_od: CMake searches <prefix> for every PATH entry <prefix>/bin, so the
# environment whose bin folder is on the PATH (an activated venv, /usr/local, ~/.local) is found
# without -Dcantools_od_DIR. It hands over to the CMake package inside the Python package.
include("${CMAKE_CURRENT_LIST_DIR}/cantools_odLocate.cmake")
if(_cantools_od_package_dir)
  include("${_cantools_od_package_dir}/cantools_odConfig.cmake")
else()
  set(cantools_od_FOUND FALSE)
  set(cantools_od_NOT_FOUND_MESSAGE
      "${CMAKE_CURRENT_LIST_DIR} belongs to a cantools-od installation whose `cantools-od cmake-dir` did not answer")
endif()
