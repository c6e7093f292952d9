# CMake integration of cantools-od: generate code from a CANopen EDS/DCF or XDD/XDC at build time.
#
#   cantools_od_generate(<target> EDS <file> | XDD <file>
#                        [NAME <name>] [TARGETS c|rust|python|markdown|html|canopennode ...]
#                        [NODE_ID <n>] [OUTPUT_DIR <dir>] [PINS <file>] [CAN_FD] [KEEP_GOING] [OD_NAME <name>])
#
# Adds a custom command that runs `cantools-od gen` whenever the EDS (or the pin file, or the
# cantools-od installation) changes. For the `c` target (the default), <name>.c is added to
# <target>'s sources and OUTPUT_DIR to its include directories, so `#include "<name>.h"` works.
# Other targets are generated into OUTPUT_DIR as part of building <target>.
# XDD <file> names a CiA 311 XML device description (.xdd, .xdc, or CANopenEditor's .xpd)
# instead of an EDS; everything below said of the EDS holds for it.
#
#   NAME        base name of the files and C symbols; default: the EDS file name without its
#               extension, lower-cased, with every run of other characters than letters and
#               digits made one `_`.
#   NODE_ID     the node-ID that $NODEID stands for (1-127).
#   OUTPUT_DIR  default: ${CMAKE_CURRENT_BINARY_DIR}/cantools_od
#   PINS        a pin file of identifiers (`cantools-od ids`); default: <EDS stem>.ids.toml beside
#               the EDS, whether it exists yet or not: creating, editing or deleting it regenerates.
#   CAN_FD      allow PDOs of up to 64 bytes.
#   KEEP_GOING  an error in the EDS that touches generated code fails the build unless this is
#               given; with it, what the errors touch is left out (and listed in the generated
#               files' header comments and in the build output) and the rest is generated.
#   OD_NAME     for the `canopennode` target: the base name of CANopenNode's object dictionary
#               files and symbols; default OD (OD.h/OD.c, which CANopen.c includes). Like `c`,
#               the target adds <OD_NAME>.c to <target>'s sources and OUTPUT_DIR to its include
#               directories. Its settings file <EDS stem>.canopennode.toml beside the EDS is tracked
#               like the default pin file: creating, editing or deleting it regenerates.
#
# Call it in the directory that defines <target> (CMake attaches custom commands to targets of the
# same directory). Which cantools-od runs:
#   CANTOOLS_OD_COMMAND     (cache, a ;-list) a command that runs cantools-od, for example
#                           "/usr/bin/python3;-m;cantools_od"; wins when set.
#   CANTOOLS_OD_EXECUTABLE  (cache) the `cantools-od` console script; searched for next to the
#                           Python installation this module belongs to first, then on the PATH.

include_guard(GLOBAL)

if(CMAKE_VERSION VERSION_LESS 3.13)
  message(FATAL_ERROR "cantools_od.cmake needs CMake 3.13 or newer (this is ${CMAKE_VERSION})")
endif()

# Policies are recorded with the function and apply to the commands it creates.
cmake_policy(PUSH)
cmake_policy(VERSION 3.13)
if(POLICY CMP0116)
  cmake_policy(SET CMP0116 NEW) # Ninja: depfile paths are relative to the binary dir or absolute
endif()

set(_cantools_od_module_dir "${CMAKE_CURRENT_LIST_DIR}")

set(CANTOOLS_OD_COMMAND "" CACHE STRING
    "Command (a ;-list) that runs cantools-od, e.g. python3;-m;cantools_od; empty: CANTOOLS_OD_EXECUTABLE")

function(_cantools_od_command out)
  if(CANTOOLS_OD_COMMAND)
    set(${out} "${CANTOOLS_OD_COMMAND}" PARENT_SCOPE)
    return()
  endif()
  # The module lives in <prefix>/lib/pythonX.Y/site-packages/cantools_od/cmake (POSIX) or
  # <prefix>/Lib/site-packages/cantools_od/cmake (Windows); the console script in <prefix>/bin or
  # <prefix>/Scripts.
  get_filename_component(_prefix "${_cantools_od_module_dir}/../../../../.." ABSOLUTE)
  get_filename_component(_windows_prefix "${_cantools_od_module_dir}/../../../.." ABSOLUTE)
  set(_hints "${_prefix}/bin" "${_windows_prefix}/Scripts")
  if(Python3_EXECUTABLE)
    get_filename_component(_python_dir "${Python3_EXECUTABLE}" DIRECTORY)
    list(APPEND _hints "${_python_dir}")
  endif()
  find_program(CANTOOLS_OD_EXECUTABLE NAMES cantools-od HINTS ${_hints} DOC "The cantools-od console script")
  if(NOT CANTOOLS_OD_EXECUTABLE)
    message(FATAL_ERROR "cantools-od not found: install it (pip install cantools-od), or set "
                        "CANTOOLS_OD_EXECUTABLE to the console script or CANTOOLS_OD_COMMAND to a command")
  endif()
  set(${out} "${CANTOOLS_OD_EXECUTABLE}" PARENT_SCOPE)
endfunction()

function(_cantools_od_default_name eds out)
  get_filename_component(_stem "${eds}" NAME_WE)
  string(TOLOWER "${_stem}" _name)
  string(REGEX REPLACE "[^a-z0-9]+" "_" _name "${_name}")
  string(REGEX REPLACE "^_+|_+$" "" _name "${_name}")
  if(_name STREQUAL "")
    set(_name "od")
  elseif(_name MATCHES "^[0-9]")
    set(_name "n_${_name}")
  endif()
  set(${out} "${_name}" PARENT_SCOPE)
endfunction()

function(cantools_od_generate target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "CAN_FD;KEEP_GOING" "EDS;XDD;NAME;NODE_ID;OUTPUT_DIR;PINS;OD_NAME" "TARGETS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "cantools_od_generate: unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET "${target}")
    message(FATAL_ERROR "cantools_od_generate: ${target} is not a target")
  endif()
  if(arg_EDS AND arg_XDD)
    message(FATAL_ERROR "cantools_od_generate(${target}): give EDS <file> or XDD <file>, not both")
  endif()
  if(arg_XDD)
    set(arg_EDS "${arg_XDD}")  # the generator tells the formats apart by their content
  endif()
  if(NOT arg_EDS)
    message(FATAL_ERROR "cantools_od_generate(${target}): EDS <file> (or XDD <file>) is required")
  endif()
  get_filename_component(_eds "${arg_EDS}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(arg_NAME)
    set(_name "${arg_NAME}")
  else()
    _cantools_od_default_name("${_eds}" _name)
  endif()
  if(NOT arg_TARGETS)
    set(arg_TARGETS c)
  endif()
  foreach(_kind IN LISTS arg_TARGETS)
    if(NOT _kind MATCHES "^(c|rust|python|markdown|html|canopennode)$")
      message(FATAL_ERROR
              "cantools_od_generate(${target}): unknown target '${_kind}' (c, rust, python, markdown, html, canopennode)")
    endif()
  endforeach()
  if(arg_OUTPUT_DIR)
    get_filename_component(_out "${arg_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  else()
    set(_out "${CMAKE_CURRENT_BINARY_DIR}/cantools_od")
  endif()
  set(_work "${CMAKE_CURRENT_BINARY_DIR}/cantools_od_${_name}")
  file(MAKE_DIRECTORY "${_out}" "${_work}")

  _cantools_od_command(_command)
  set(_options -o "${_out}")
  set(_depends "${_eds}")
  if(arg_NODE_ID)
    list(APPEND _options --node-id "${arg_NODE_ID}")
  endif()
  if(arg_CAN_FD)
    list(APPEND _options --can-fd)
  endif()
  if(arg_KEEP_GOING)
    list(APPEND _options --keep-going)
  endif()
  if(arg_PINS)
    get_filename_component(_pins "${arg_PINS}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    list(APPEND _options --pins "${_pins}")
    list(APPEND _depends "${_pins}")
  endif()
  get_filename_component(_eds_name "${_eds}" NAME)
  string(REGEX REPLACE "\\.[^./]*$" "" _eds_base "${_eds}")
  if(NOT arg_PINS)
    _cantools_od_track("${target}" "${_name}_pins" "${_eds_base}.ids.toml" "${_work}/pins.ids.toml"
                       "Checking ${_eds_name}'s pin file")
    list(APPEND _depends "${_work}/pins.ids.toml")
  endif()
  list(GET _command 0 _program)
  if(IS_ABSOLUTE "${_program}" AND EXISTS "${_program}" AND NOT CANTOOLS_OD_COMMAND)
    list(APPEND _depends "${_program}") # regenerate after cantools-od is upgraded
  endif()
  get_target_property(_type "${target}" TYPE)
  if(_type STREQUAL "INTERFACE_LIBRARY")
    set(_scope INTERFACE)
    set(_sources_scope INTERFACE)
  else()
    set(_scope PUBLIC)
    set(_sources_scope PRIVATE)
  endif()
  set(_others "${arg_TARGETS}")
  list(REMOVE_ITEM _others c canopennode)
  if("c" IN_LIST arg_TARGETS)
    set(_outputs "${_out}/${_name}.h" "${_out}/${_name}.c")
    # gen rewrites a file only when its content changes. Ninja (restat) then skips what depends on an
    # unchanged file; other build tools would run the generator again and again while the EDS is newer
    # than the outputs, so they get fresh timestamps there.
    set(_touch)
    if(NOT CMAKE_GENERATOR MATCHES "Ninja")
      set(_touch COMMAND "${CMAKE_COMMAND}" -E touch_nocreate ${_outputs})
    endif()
    add_custom_command(
      OUTPUT ${_outputs}
      COMMAND ${_command} gen "${_eds}" -t c --name "${_name}" ${_options}
      ${_touch}
      DEPENDS ${_depends}
      COMMENT "Generating ${_name}.h and ${_name}.c from ${_eds_name}"
      VERBATIM)
    target_sources("${target}" ${_sources_scope} ${_outputs})
    target_include_directories("${target}" ${_scope} "${_out}")
  endif()
  if("canopennode" IN_LIST arg_TARGETS)
    _cantools_od_track("${target}" "${_name}_canopennode" "${_eds_base}.canopennode.toml"
                       "${_work}/canopennode.toml" "Checking ${_eds_name}'s canopennode settings")
    _cantools_od_canopennode("${target}" "${_eds}" "${_out}" "${_work}" "${arg_OD_NAME}" "${_command}"
                             "${_options}" "${_depends};${_work}/canopennode.toml" "${_scope}" "${_sources_scope}")
  endif()
  if(_others)
    # The file names of these targets are not known here: a stamp file stands for them.
    set(_stamp "${_work}/others.stamp")
    set(_target_options)
    foreach(_kind IN LISTS _others)
      list(APPEND _target_options -t "${_kind}")
    endforeach()
    add_custom_command(
      OUTPUT "${_stamp}"
      COMMAND ${_command} gen "${_eds}" ${_target_options} --name "${_name}" ${_options}
      COMMAND "${CMAKE_COMMAND}" -E touch "${_stamp}"
      DEPENDS ${_depends}
      COMMENT "Generating ${_others} for ${_name} from ${_eds_name}"
      VERBATIM)
    target_sources("${target}" ${_sources_scope} "${_stamp}")
  endif()
endfunction()

# An optional input beside the EDS (the pin file, the canopennode settings) may not exist yet, and a
# build step cannot depend on a missing file: a target run on every build keeps a copy of it in the
# build folder (empty while there is none), rewritten only when that changes; generation depends on
# the copy.
function(_cantools_od_track target key tracked copy comment)
  add_custom_target("${target}_cantools_od_${key}" ALL
    COMMAND "${CMAKE_COMMAND}" "-DTRACKED=${tracked}" "-DCOPY=${copy}"
            -P "${_cantools_od_module_dir}/cantools_od_track.cmake"
    BYPRODUCTS "${copy}"
    COMMENT "${comment}"
    VERBATIM)
  get_target_property(_target_type "${target}" TYPE)
  if(NOT _target_type STREQUAL "INTERFACE_LIBRARY" OR NOT CMAKE_VERSION VERSION_LESS 3.19)
    add_dependencies("${target}" "${target}_cantools_od_${key}") # also when building only it
  endif()
endfunction()

# The canopennode target: CANopenNode v4's <OD_NAME>.h/.c, compiled into <target>.
function(_cantools_od_canopennode target eds out work od_name command options depends scope sources_scope)
  if(NOT od_name)
    set(od_name OD)
  endif()
  get_filename_component(_eds_name "${eds}" NAME)
  set(_outputs "${out}/${od_name}.h" "${out}/${od_name}.c")
  set(_touch) # as for `c`: fresh timestamps where the build tool does not restat
  if(NOT CMAKE_GENERATOR MATCHES "Ninja")
    set(_touch COMMAND "${CMAKE_COMMAND}" -E touch_nocreate ${_outputs})
  endif()
  add_custom_command(
    OUTPUT ${_outputs}
    COMMAND ${command} gen "${eds}" -t canopennode --name "${od_name}" ${options}
    ${_touch}
    DEPENDS ${depends} # the EDS, the pin file and the settings file: no depfile needed
    COMMENT "Generating ${od_name}.h and ${od_name}.c (CANopenNode) from ${_eds_name}"
    VERBATIM)
  target_sources("${target}" ${sources_scope} ${_outputs})
  target_include_directories("${target}" BEFORE ${scope} "${out}")
endfunction()

cmake_policy(POP)

include("${_cantools_od_module_dir}/cantools_od_bus.cmake") # cantools_od_bus(<bus>): ros2_canopen's cogen_dcf
