# Sourced by the RTL check scripts. rtl_declares RTL_DIR MODULE NAME: whether MODULE declares the
# parameter NAME. rastersim_core and rastersim_top declare the core's list through the
# RASTERSIM_CORE_PARAMETERS macro of rastersim_core_parameters.vh.
rtl_declares() {
  grep -q "parameter integer $3\b" "$1/$2.sv" ||
    { grep -q '`RASTERSIM_CORE_PARAMETERS\b' "$1/$2.sv" && grep -q "parameter integer $3\b" "$1/rastersim_core_parameters.vh"; }
}
