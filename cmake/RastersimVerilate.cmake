# How the RTL is verilated, once for the main build (testbench/, testbench/systemc/) and for the
# modules built on demand for profiles the build lacks (testbench/ondemand/, docs/debugging.md).
# Expects the verilate() function (find_package(verilator)).

get_filename_component(RASTERSIM_SOURCE_ROOT ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
set(RASTERSIM_RTL_DIR ${RASTERSIM_SOURCE_ROOT}/rtl)
set(RASTERSIM_RTL_SOURCES
  ${RASTERSIM_RTL_DIR}/rastersim_pkg.sv  # first: the units include it too (its guard makes either work)
  ${RASTERSIM_RTL_DIR}/rastersim_top.sv
  ${RASTERSIM_RTL_DIR}/triangle_setup.sv
  ${RASTERSIM_RTL_DIR}/triangle_setup_serial.sv
  ${RASTERSIM_RTL_DIR}/triangle_setup_pipelined.sv
  ${RASTERSIM_RTL_DIR}/setup_fifo.sv
  ${RASTERSIM_RTL_DIR}/span_bounds.sv
  ${RASTERSIM_RTL_DIR}/scanline_walker_entry.sv
  ${RASTERSIM_RTL_DIR}/scanline_walker.sv
  ${RASTERSIM_RTL_DIR}/z_adder.sv
  ${RASTERSIM_RTL_DIR}/plane_register.sv
  ${RASTERSIM_RTL_DIR}/zbuffer.sv
  ${RASTERSIM_RTL_DIR}/zbuffer_memory.sv
  ${RASTERSIM_RTL_DIR}/rastersim_core.sv
)
# The debug monitor bound into rastersim_top for waveforms (frame cycle, triangle per unit).
set(RASTERSIM_RTL_DEBUG_SOURCES ${RASTERSIM_SOURCE_ROOT}/testbench/rtl/rastersim_debug.sv)

# A configuration entry "name:NAME=value,NAME=value,..." (parameters of rtl/rastersim_core.sv; the
# others keep their defaults there) into <prefix>_NAME and <prefix>_GENERICS (its -G arguments).
# The program reads what was built back from the verilated core (its P_* constants), so this list is
# data, not a mapping: model/core_parameters.h maps a profile to these names.
function(rastersim_parse_config config prefix)
  if(NOT config MATCHES "^([A-Za-z0-9_]+):(.*)$")
    message(FATAL_ERROR "RTL configuration '${config}' is not name:NAME=value,NAME=value,... (an entry cached by an older build: configure with -URASTERSIM_RTL_CONFIGS)")
  endif()
  set(name ${CMAKE_MATCH_1})
  string(REPLACE "," ";" assignments "${CMAKE_MATCH_2}")
  set(generics "")
  foreach(assignment ${assignments})
    if(NOT assignment MATCHES "^[A-Z][A-Z0-9_]*=-?[0-9]+$")
      message(FATAL_ERROR "RTL configuration '${config}': '${assignment}' is not NAME=integer")
    endif()
    list(APPEND generics -G${assignment})
  endforeach()
  set(${prefix}_NAME ${name} PARENT_SCOPE)
  set(${prefix}_GENERICS ${generics} PARENT_SCOPE)
endfunction()

# Verilates one configuration into <target>: rastersim_top (plain C++, FST tracing, the debug
# monitor bound in) for the RTL backend, or with SYSTEMC rastersim_core as a SystemC module.
# Adds the generated folder to the target's include path (its __Syms.h names rastersim_core's class).
function(rastersim_verilate target prefix config)
  cmake_parse_arguments(ARG "SYSTEMC" "" "" ${ARGN})
  rastersim_parse_config("${config}" cfg)
  if(ARG_SYSTEMC)
    set(kind SYSTEMC)
    set(top rastersim_core)
    set(sources ${RASTERSIM_RTL_SOURCES})
    set(trace "")
  else()
    set(kind "")
    set(top rastersim_top)
    set(sources ${RASTERSIM_RTL_SOURCES} ${RASTERSIM_RTL_DEBUG_SOURCES})
    set(trace TRACE_FST)
  endif()
  verilate(${target} ${kind}
    SOURCES ${sources}
    PREFIX ${prefix}
    TOP_MODULE ${top}
    ${trace}
    INCLUDE_DIRS ${RASTERSIM_RTL_DIR}
    VERILATOR_ARGS
      ${cfg_GENERICS}
      --x-assign unique --x-initial unique
      --assert  # the units' assertions (rtl/rastersim_assert.vh): a failure ends the frame
      -Wno-fatal -Werror-USERERROR  # lint cleanliness is its own test (rtl/CMakeLists.txt); illegal parameters stop
    OPT_GLOBAL -w
    OPT_FAST -w -O2
    OPT_SLOW -w -O1)
  # Verilator's headers and the generated ones are not ours to warn about.
  get_target_property(binary_dir ${target} BINARY_DIR)
  target_include_directories(${target} SYSTEM PUBLIC ${binary_dir}/CMakeFiles/${target}.dir/${prefix}.dir
                             ${VERILATOR_ROOT}/include ${VERILATOR_ROOT}/include/vltstd)
endfunction()

# The SystemC system model at one configuration (docs/systemc.md): rastersim_core verilated with
# --sc, with the command FIFO and the z-buffer memory model.
#  - rastersim_systemc_core: static, for SystemC programs (the platform example, a user's own).
#  - rastersim_systemc: a shared library with the backend API (systemc_backend.h) that keeps its
#    Verilator runtime (built for SystemC, VM_SC=1) private, so that rastersim links it next to the
#    plain verilated RTL (rastersim_rtl, VM_SC=0).
# Expects PkgConfig::SYSTEMC.
function(rastersim_systemc_targets config)
  set(sc_dir ${RASTERSIM_SOURCE_ROOT}/testbench/systemc)
  set(sc_sources ${sc_dir}/command_fifo.cpp ${sc_dir}/zbuffer_memory_model.cpp ${sc_dir}/texture_memory_model.cpp
                 ${sc_dir}/rastersim_system.cpp)
  add_library(rastersim_systemc_core STATIC ${sc_sources}
    # The register range checks of the setup record it reads (model/fixed.h): the shared library
    # takes nothing from the program, and the model library is not position-independent.
    ${RASTERSIM_SOURCE_ROOT}/model/fixed.cpp ${RASTERSIM_SOURCE_ROOT}/model/core_parameters.cpp)
  # Linked into the shared library; hidden so that its Verilator runtime never meets rastersim_rtl's.
  set_target_properties(rastersim_systemc_core PROPERTIES POSITION_INDEPENDENT_CODE ON
                        CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  target_include_directories(rastersim_systemc_core PUBLIC ${RASTERSIM_SOURCE_ROOT})
  target_link_libraries(rastersim_systemc_core PUBLIC PkgConfig::SYSTEMC)
  set_source_files_properties(${sc_sources} PROPERTIES COMPILE_OPTIONS "${RASTERSIM_WARNINGS}")
  rastersim_verilate(rastersim_systemc_core Vrastersim_sc "${config}" SYSTEMC)

  add_library(rastersim_systemc SHARED ${sc_dir}/systemc_backend.cpp)
  set_target_properties(rastersim_systemc PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  target_compile_options(rastersim_systemc PRIVATE ${RASTERSIM_WARNINGS})
  target_include_directories(rastersim_systemc PUBLIC ${RASTERSIM_SOURCE_ROOT})
  # Self-contained (no symbol from the program), nothing of the static core exported.
  target_link_libraries(rastersim_systemc PRIVATE rastersim_systemc_core -Wl,--exclude-libs,ALL -Wl,--no-undefined)
  target_link_libraries(rastersim_systemc PUBLIC PkgConfig::SYSTEMC)
endfunction()
