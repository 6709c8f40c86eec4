// The RTL backend's module built on demand (CMakeLists.txt beside): one verilated rastersim_top as
// a configuration the program registers (rtl_backend.h load_module), and its ABI stamp.
#include "Vrastersim_module.h"
#include "Vrastersim_module__Syms.h"
#include "testbench/modules.h"
#include "testbench/rtl_configs.h"
#include "testbench/rtl_configuration.h"

namespace {
using Core = rastersim::rtl::detail::CoreOf<Vrastersim_module>;
}  // namespace

extern "C" __attribute__((visibility("default"))) const rastersim::rtl::BuiltConfiguration* rastersim_rtl_module() {
  static const rastersim::rtl::BuiltConfiguration configuration = {
      "on demand", rastersim::parameters_of<Core>(),
      &rastersim::rtl::detail::run_configuration<Vrastersim_module>};
  return &configuration;
}

extern "C" __attribute__((visibility("default"))) const char* rastersim_module_abi() {
  static const std::string stamp = rastersim::modules::abi_stamp();
  return stamp.c_str();
}
