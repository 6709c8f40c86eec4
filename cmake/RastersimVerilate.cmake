# How the RTL is verilated, once for the main build (testbench/, testbench/systemc/) and for the
# modules built on demand for profiles the build lacks (testbench/ondemand/, docs/debugging.md).
# Expects the verilate() function (find_package(verilator)).

get_filename_component(RASTERSIM_SOURCE_ROOT ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
set(RASTERSIM_RTL_DIR ${RASTERSIM_SOURCE_ROOT}/rtl)
set(RASTERSIM_RTL_SOURCES
  ${RASTERSIM_RTL_DIR}/rastersim_top.sv
  ${RASTERSIM_RTL_DIR}/triangle_setup.sv
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

# A configuration entry "name:width:height:subpixel_bits:z_bits:z_guard_bits:max_memory_latency
# [:setup_interval[:texture[:depth_exponent_bits[:depth_bias]]]]" (z_guard_bits 0 = derived) into
# <prefix>_NAME, _WIDTH, _HEIGHT, _SUBPIXEL_BITS, _Z_BITS, _Z_GUARD_BITS, _MAX_LATENCY,
# _SETUP_INTERVAL, _TEXTURE, _DEPTH_EXPONENT_BITS, _DEPTH_BIAS and _GENERICS (the -G arguments of
# rastersim_core).
function(rastersim_parse_config config prefix)
  string(REPLACE ":" ";" fields "${config}")
  list(LENGTH fields field_count)
  if(field_count LESS 7 OR field_count GREATER 11)
    message(FATAL_ERROR "RTL configuration '${config}' is not name:width:height:subpixel_bits:z_bits:z_guard_bits:max_memory_latency[:setup_interval[:texture[:depth_exponent_bits[:depth_bias]]]]")
  endif()
  # The optional fields 7..10, with their values for an entry written before each existed: the
  # default setup, no texture unit, the fixed-point depth word, no depth bias.
  set(optional_fields setup_interval texture depth_exponent_bits depth_bias)
  set(optional_defaults 4 0 0 0)
  foreach(i RANGE 3)
    list(GET optional_fields ${i} field)
    math(EXPR at "7 + ${i}")
    if(field_count GREATER at)
      list(GET fields ${at} ${field})
    else()
      list(GET optional_defaults ${i} ${field})
    endif()
  endforeach()
  list(GET fields 0 name)
  list(GET fields 1 width)
  list(GET fields 2 height)
  list(GET fields 3 subpixel_bits)
  list(GET fields 4 z_bits)
  list(GET fields 5 z_guard_bits)
  list(GET fields 6 max_latency)
  foreach(field name width height subpixel_bits z_bits z_guard_bits max_latency setup_interval texture
          depth_exponent_bits depth_bias)
    string(TOUPPER ${field} upper)
    set(${prefix}_${upper} ${${field}} PARENT_SCOPE)
  endforeach()
  set(${prefix}_GENERICS
      -GWIDTH=${width} -GHEIGHT=${height} -GSUBPIXEL_BITS=${subpixel_bits} -GZ_BITS=${z_bits}
      -GZ_GUARD_BITS=${z_guard_bits} -GMAX_MEMORY_LATENCY=${max_latency} -GSETUP_INTERVAL=${setup_interval}
      -GTEXTURE=${texture} -GDEPTH_EXPONENT_BITS=${depth_exponent_bits} -GDEPTH_BIAS=${depth_bias}
      PARENT_SCOPE)
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
    ${RASTERSIM_SOURCE_ROOT}/model/fixed.cpp)
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
