# find_package(cantools_od CONFIG) entry point. `cantools-od cmake-dir` prints this folder:
#   cmake -S . -B build -Dcantools_od_DIR="$(cantools-od cmake-dir)"
# or list(APPEND CMAKE_PREFIX_PATH <that folder>) before find_package(cantools_od CONFIG).
include("${CMAKE_CURRENT_LIST_DIR}/cantools_od.cmake")
