# ros2_canopen configuration packages: a bus configuration built by cantools-od, as ros2_canopen's
# `cogen_dcf(<bus>)` (lely_core_libraries) builds it with cogen and dcfgen.
#
#   cantools_od_bus(<bus> [CONFIG_DIR <dir>] [OUTPUT_DIR <dir>] [DESTINATION <dir>] [NO_INSTALL])
#
# Reads <CONFIG_DIR>/bus.yml (default: ${CMAKE_CURRENT_SOURCE_DIR}/config/<bus>) and writes into
# OUTPUT_DIR (default: ${CMAKE_BINARY_DIR}/config/<bus>, as cogen_dcf) master.dcf, the concise DCFs
# (<node>.bin, master.bin) and bus.yml as ros2_canopen installs it (defaults copied over each node,
# as cogen does). @BUS_CONFIG_PATH@ stands for ${CMAKE_INSTALL_PREFIX}/<DESTINATION>, DESTINATION
# being share/${PROJECT_NAME}/config/<bus> by default. A target <bus>, built by default, runs
# `cantools-od network` again when bus.yml or an EDS/DCF of CONFIG_DIR changes (and only then); its
# network checks fail the build with file:line. Unless NO_INSTALL, CONFIG_DIR (without its bus.yml)
# and OUTPUT_DIR are installed into DESTINATION, as cogen_dcf installs them.

include_guard(GLOBAL)

# `given` made absolute against `base`, or `default` when not given.
function(_cantools_od_folder out given base default)
  if(given)
    get_filename_component(default "${given}" ABSOLUTE BASE_DIR "${base}")
  endif()
  set(${out} "${default}" PARENT_SCOPE)
endfunction()

function(cantools_od_bus bus)
  cmake_parse_arguments(PARSE_ARGV 1 arg "NO_INSTALL" "CONFIG_DIR;OUTPUT_DIR;DESTINATION" "")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "cantools_od_bus: unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  _cantools_od_folder(_config "${arg_CONFIG_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}/config/${bus}")
  if(NOT EXISTS "${_config}/bus.yml")
    message(FATAL_ERROR "cantools_od_bus(${bus}): ${_config}/bus.yml does not exist")
  endif()
  _cantools_od_folder(_out "${arg_OUTPUT_DIR}" "${CMAKE_CURRENT_BINARY_DIR}" "${CMAKE_BINARY_DIR}/config/${bus}")
  if(arg_DESTINATION)
    set(_destination "${arg_DESTINATION}")
  else()
    set(_destination "share/${PROJECT_NAME}/config/${bus}")
  endif()
  set(_work "${CMAKE_CURRENT_BINARY_DIR}/cantools_od_bus_${bus}")
  file(MAKE_DIRECTORY "${_out}" "${_work}")

  _cantools_od_command(_command)
  # The nodes' files: the EDS/DCF files beside bus.yml, where dcfgen (run in that folder) finds them.
  # CONFIGURE_DEPENDS: a file added later is found on the next build.
  file(GLOB _nodes CONFIGURE_DEPENDS "${_config}/*.eds" "${_config}/*.EDS" "${_config}/*.dcf" "${_config}/*.DCF")
  set(_depends "${_config}/bus.yml" ${_nodes})
  list(GET _command 0 _program)
  if(IS_ABSOLUTE "${_program}" AND EXISTS "${_program}" AND NOT CANTOOLS_OD_COMMAND)
    list(APPEND _depends "${_program}") # again after cantools-od is upgraded
  endif()
  set(_stamp "${_work}/network.stamp") # the .bin files' names follow the nodes: a stamp stands for them
  add_custom_command(
    OUTPUT "${_stamp}"
    BYPRODUCTS "${_out}/master.dcf" "${_out}/bus.yml"
    COMMAND ${_command} network "${_config}/bus.yml" -r --no-node-dcf -o "${_out}" --write-bus "${_out}/bus.yml"
            --define "BUS_CONFIG_PATH=${CMAKE_INSTALL_PREFIX}/${_destination}"
    COMMAND "${CMAKE_COMMAND}" -E touch "${_stamp}"
    DEPENDS ${_depends}
    WORKING_DIRECTORY "${_config}"
    COMMENT "Generating the ${bus} bus configuration (master.dcf, concise DCFs) from bus.yml"
    VERBATIM)
  add_custom_target("${bus}" ALL DEPENDS "${_stamp}")
  if(NOT arg_NO_INSTALL)
    install(DIRECTORY "${_config}/" DESTINATION "${_destination}" PATTERN "bus.yml" EXCLUDE)
    install(DIRECTORY "${_out}/" DESTINATION "${_destination}" PATTERN ".cantools-od-network" EXCLUDE)
  endif()
endfunction()
