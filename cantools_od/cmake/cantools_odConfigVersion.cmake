# The version of the cantools-od package this folder belongs to, read from its __init__.py,
# so that find_package(cantools_od 0.1 CONFIG) can check it.
file(STRINGS "${CMAKE_CURRENT_LIST_DIR}/../__init__.py" _cantools_od_version_line
     REGEX "^__version__ = \"[^\"]+\"" LIMIT_COUNT 1)
string(REGEX REPLACE "^__version__ = \"([^\"]+)\".*" "\\1" PACKAGE_VERSION "${_cantools_od_version_line}")
unset(_cantools_od_version_line)
if(PACKAGE_FIND_VERSION AND PACKAGE_VERSION VERSION_LESS PACKAGE_FIND_VERSION)
  set(PACKAGE_VERSION_COMPATIBLE FALSE)
else()
  set(PACKAGE_VERSION_COMPATIBLE TRUE)
  if(PACKAGE_FIND_VERSION AND PACKAGE_VERSION VERSION_EQUAL PACKAGE_FIND_VERSION)
    set(PACKAGE_VERSION_EXACT TRUE)
  endif()
endif()
