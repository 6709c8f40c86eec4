#!/usr/bin/env bash
# Bug injection: copies rtl/ with one bug each, verilates the copy (64 x 48 profile) with
# testbench/mutant_check.cpp (the setup_* mutants with the pipelined setup, SETUP_INTERVAL 2; the
# serial_* mutants with the serial setup, SETUP_INTERVAL 0) and requires the co-simulation to catch
# the bug with a first-divergence report: first with the frames of `rastersim cosim --count 100`
# (directed, coverage and random frames), then with more suites unless the mutant is marked
# --cosim-only. Usage: rtl-mutants.sh BUILD_DIR [mutant ...]  (BUILD_DIR holds librastersim_rtl.a).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:?usage: rtl-mutants.sh BUILD_DIR [mutant ...]}" && pwd)"
shift
mutants=("$@")
[ ${#mutants[@]} -eq 0 ] && mutants=(bbox_coverage walker_backpressure walker_no_overlap walker_first_row_span
                                     walker_empty_row walker_dda_carry walker_record_carry walker_lower_bound_order
                                     walker_bounds_cross walker_last_offset entry_quot_carry entry_left_carry_1
                                     walker_covered_first entry_covered_first
                                     z_adder_first_row z_adder_carry z_adder_slot_carry
                                     z_adder_slot_step walker_enter_slot walker_left_carry_1 hazard_stall
                                     hazard_window_short hazard_address_bit ring_read_slot hazard_last_read
                                     hazard_taken_slot hazard_waiting_slot buffer_one_entry done_last_read
                                     serial_floor serial_remainder_correction serial_multiplier_bits
                                     serial_bias_carry serial_product_step_x setup_slot_counter setup_floor_correction setup_missing_step
                                     setup_credit_count setup_fifo_empty setup_edge_sign setup_offscreen_rows)

# The texture unit's mutants (TEXTURE 1, pipelined setup; not in the default list: ctest
# rtl.injected_texture_bugs_are_caught, label long, runs them by name); the sampler's must be caught
# by the directed frames alone:
texture_mutants=(texture_capacity texture_bank_route texture_stall_ignored texture_untextured_waits
                 texture_left_slots)
texture_sampler_mutants=(texture_clamp_below texture_blend_rounding)
# The depth output stage's (DEPTH_EXPONENT_BITS 3, DEPTH_BIAS 1; ctest rtl.injected_depth_bugs_are_caught,
# label long):
depth_mutants=(depth_bias_shift depth_bias_smaller_step depth_float_mantissa depth_bias_slope_unsigned depth_bias_ready_early
              depth_bias_low_carry)
# name -> file, text to replace, replacement (fixed strings); params: extra verilator -G settings;
# check: mutant_check's mode (--cosim-only: the frames of `rastersim cosim --count 100` must catch it;
# --directed-only: its directed and coverage frames).
declare -A file from to params check
max_latency=8
file[bbox_coverage]=scanline_walker.sv
from[bbox_coverage]='frag_x + 1'"'"'b1 <= x_end_q;'
to[bbox_coverage]='frag_x + 1'"'"'b1 < x_end_q;'  # bbox: each row's last covered pixel (after its first) dropped
file[walker_backpressure]=scanline_walker.sv
from[walker_backpressure]='wire advance = walking_q && (frag_ready || !frag_valid);'
to[walker_backpressure]='wire advance = walking_q;'  # the walker ignores the z-buffer's back-pressure
params[walker_backpressure]="-GSETUP_INTERVAL=4"  # back-to-back triangles: hazard stalls happen
check[walker_backpressure]=--cosim-only  # once it survived 100 random frames; the coverage frames reach hazards
# The walker's overlapped load and its span look-ahead.
file[walker_no_overlap]=scanline_walker.sv
from[walker_no_overlap]='assign in_ready = !walking_q || last;'
to[walker_no_overlap]='assign in_ready = !walking_q;'  # the next record waits for a cycle of its own
params[walker_no_overlap]="-GSETUP_INTERVAL=4"  # records waiting in the FIFO: loads overlap
file[walker_first_row_span]=scanline_walker.sv
from[walker_first_row_span]='x_end_q <= in_entry[LSB_SPAN_END +: X_BITS];'
to[walker_first_row_span]='x_end_q <= span_end;'  # the first row's span end from the last triangle's DDA
file[walker_empty_row]=scanline_walker.sv
from[walker_empty_row]='row_empty_q <= !span_nonempty;'
to[walker_empty_row]='row_empty_q <= 1'"'"'b0;'  # an empty row presents a fragment
# The span's one-level compares and the DDA's carry.
file[walker_dda_carry]=scanline_walker.sv
from[walker_dda_carry]='assign dda_carry[g] = !rem_sum[REM_BITS-1];'
to[walker_dda_carry]='assign dda_carry[g] = !rem_sum[REM_BITS-1] && |rem_sum;'  # no carry when rem + step_rem == d
file[walker_record_carry]=scanline_walker_entry.sv
from[walker_record_carry]='minus_d_less << 1, {2{!step_x_negative}}'
to[walker_record_carry]='minus_d_less << 1, {1'"'"'b0, !step_x_negative}'  # the second row's remainder after a carry one too high
file[walker_lower_bound_order]=span_bounds.sv
from[walker_lower_bound_order]='(lo_small[0] && lo_small[1] && low[0] <= low[1])'
to[walker_lower_bound_order]='(lo_small[0] && lo_small[1] && low[0] >= low[1])'  # the smaller of two left-edge bounds starts the span
file[walker_bounds_cross]=span_bounds.sv
from[walker_bounds_cross]='hi_none[h] || !sum[X_BITS+1]'
to[walker_bounds_cross]='hi_none[h] || 1'"'"'b1'  # a left bound past a right one does not empty the row
file[walker_last_offset]=scanline_walker_entry.sv
from[walker_last_offset]='sum3_offset(x1_wide, minus_x0_less_1, ~{2'"'"'b00'
to[walker_last_offset]='sum3_offset(x1_wide + 1'"'"'b1, minus_x0_less_1, ~{2'"'"'b00'  # the first row's right bound may lie one past the box
# (one short instead, hi < x1 - x0, is an equivalent mutant: at hi = x1 - x0 both ends are x1)
# The entry stage's second row and the walker's bbox coverage a candidate ahead.
file[entry_quot_carry]=scanline_walker_entry.sv
from[entry_quot_carry]='!(left[g] || right[g]) ? quot_k : dda_carry[g] ? quot_carried : quot_sum;'
to[entry_quot_carry]='!(left[g] || right[g]) ? quot_k : quot_sum;'  # the second row's quotient ignores the first step's carry
file[entry_left_carry_1]=scanline_walker_entry.sv
from[entry_left_carry_1]='wire [1:0] left_carry = {left[0] && left[1] ? dda_carry[1] : dda_carry[2],'
to[entry_left_carry_1]='wire [1:0] left_carry = {dda_carry[2],'  # the first row's slot 1 always takes edge 2's carry
file[walker_covered_first]=scanline_walker.sv
from[walker_covered_first]='covered_q <= span_nonempty && lo_from_x0;'
to[walker_covered_first]='covered_q <= span_nonempty;'  # bbox: x0 covered on every later non-empty row
file[entry_covered_first]=scanline_walker.sv
from[entry_covered_first]='covered_q <= !in_entry[LSB_ROW_EMPTY] && !in_entry[LSB_ENTER_LEFT];'
to[entry_covered_first]='covered_q <= !in_entry[LSB_ROW_EMPTY];'  # bbox: x0 covered on a non-empty first row
file[z_adder_first_row]=plane_register.sv
from[z_adder_first_row]='assign next_value = load ? (enter_left ? record_left[enter_slot] : start)'
to[z_adder_first_row]='assign next_value = load ? start'  # the first row's planes not moved to its span start
file[z_adder_carry]=plane_register.sv
from[z_adder_carry]=': step_x ? value_q + step_x_q'
to[z_adder_carry]=': step_x ? value_q + step_x_q + 1'"'"'b1'  # carry-in of the x-step adder flipped
# The planes along the left edges and the walker's slot and carry mapping.
file[z_adder_slot_carry]=plane_register.sv
from[z_adder_slot_carry]='assign entered[j] = carry_q[j] ? along_carry_q : along_q[j];'
to[z_adder_slot_carry]='assign entered[j] = along_q[j];'  # a carried edge's span start entered a pixel off
file[z_adder_slot_step]=plane_register.sv
from[z_adder_slot_step]='along_q[k] <= along_q[k] + (carry_q[k] ? along_step_carry_q[k] : along_step_q[k]);'
to[z_adder_slot_step]='along_q[k] <= along_q[k] + along_step_q[k];'  # a slot ignores its edge's DDA carry
file[walker_enter_slot]=span_bounds.sv
from[walker_enter_slot]='assign enter_slot = (lo_pick_1 && left[0]) || (lo_pick_2 && (left[0] || left[1]));'
to[walker_enter_slot]='assign enter_slot = lo_pick_1 || lo_pick_2;'  # edge 1 or 2 taken as slot 1 even when it is the first left edge
file[walker_left_carry_1]=scanline_walker.sv
from[walker_left_carry_1]='assign adder_left_carry = mid_walk_q ? {left_q[0] && left_q[1] ? dda_carry[1] : dda_carry[2],'
to[walker_left_carry_1]='assign adder_left_carry = mid_walk_q ? {dda_carry[2],'  # slot 1 always takes edge 2's carry
file[hazard_stall]=zbuffer.sv
from[hazard_stall]='assign mem_rd_valid = head_valid && mem_clear_done && !hazard;'
to[hazard_stall]='assign mem_rd_valid = head_valid && mem_clear_done;'  # read-after-write stall removed
params[hazard_stall]="-GSETUP_INTERVAL=4"  # a setup fast enough for back-to-back triangles to meet
# The z-buffer's live bits, its input buffer's match bits and its in-flight RAM.
for m in hazard_window_short hazard_address_bit ring_read_slot hazard_last_read hazard_taken_slot hazard_waiting_slot \
         buffer_one_entry done_last_read; do
  file[$m]=zbuffer.sv
  params[$m]="-GSETUP_INTERVAL=4"
done
from[hazard_window_short]='1'"'"'b1} << done_slot;'
to[hazard_window_short]='1'"'"'b1} << (done_slot + RING_BITS'"'"'(1));'  # the done slot one age short: results and retirement a cycle early
from[hazard_address_bit]='frag_ahead : ring_pixel_q[k] == frag_pixel;'
to[hazard_address_bit]='frag_ahead : ring_pixel_q[k][PIXEL_BITS-1:1] == frag_pixel[PIXEL_BITS-1:1];'  # the compare ignores bit 0 of x
from[ring_read_slot]='ram_read_q <= ring_data_q[read_slot];'
to[ring_read_slot]='ram_read_q <= ring_data_q[done_slot + RING_BITS'"'"'(1)];'  # the in-flight RAM read a cycle late
from[hazard_last_read]=' || (issued_q && ahead_q[head_q]);'
to[hazard_last_read]=';'  # the fragment read in the last cycle not compared with the head
from[hazard_taken_slot]='frag_match[k] = now_onehot_q[k] ? frag_ahead : ring_pixel_q[k] == frag_pixel;'
to[hazard_taken_slot]='frag_match[k] = ring_pixel_q[k] == frag_pixel;'  # a fragment taken as the head is read: the slot's old pixel
from[hazard_waiting_slot]='(ahead_q[e] ? now_onehot_q : {RING{1'"'"'b0}})'
to[hazard_waiting_slot]='{RING{1'"'"'b0}}'  # a waiting fragment not matched with the one read ahead of it
from[buffer_one_entry]='assign frag_ready = !count_q[1];'
to[buffer_one_entry]='assign frag_ready = count_q == 2'"'"'d0;'  # one entry: a fragment every other cycle
from[done_last_read]='done_live_q <= |(live & next_done_onehot);'
to[done_last_read]='done_live_q <= |(live_q & next_done_onehot);'  # at L = 2 the last cycle's read never completes
# The serial setup unit.
for m in serial_floor serial_remainder_correction serial_multiplier_bits serial_bias_carry serial_swap_deltas \
         serial_product_step_x; do
  file[$m]=triangle_setup_serial.sv
  params[$m]="-GSETUP_INTERVAL=0"
done
from[serial_floor]='wire quotient_bit = (fits && divisor_nonzero) ^ sign_q;'
to[serial_floor]='wire quotient_bit = fits && divisor_nonzero;'  # a negative dividend's quotient not inverted
from[serial_remainder_correction]='if (sign_q) rem_q <= ~trial[AREA_BITS-1:0];'
to[serial_remainder_correction]='if (1'"'"'b0) rem_q <= ~trial[AREA_BITS-1:0];'  # the span remainder correction step missing
from[serial_multiplier_bits]=': is_edge ? SB'"'"'(2 * (COORD_BITS + 1))'
to[serial_multiplier_bits]=': is_edge ? SB'"'"'(2 * COORD_BITS)'  # the edge products one multiplier bit short
from[serial_bias_carry]=': subtract || (bit_now && start_bias_q);'
to[serial_bias_carry]=': subtract;'  # the start numerators use the biased edge values
from[serial_swap_deltas]='dx_q[d] <= -dx_q[2 - d];'
to[serial_swap_deltas]='dx_q[d] <= dx_q[2 - d];'  # the swapped edges keep their x direction
from[serial_product_step_x]='product_step_x_q <= product_step_x;'
to[serial_product_step_x]='product_step_x_q <= depth_q[1];'  # the colour planes along the left edges step by the depth's step_x
# Mutants of one file, built with the same parameters, that the cosim frames alone must catch.
cosim_only_mutants() {
  local in=$1 with=$2
  shift 2
  for m in "$@"; do
    file[$m]=$in
    params[$m]=$with
    check[$m]=--cosim-only
  done
}
# The texture unit (a textured profile's cosim frames: textures, filters, wraps, stall patterns).
cosim_only_mutants texture_unit.sv "-GSETUP_INTERVAL=4 -GTEXTURE=1" "${texture_mutants[@]}"
from[texture_capacity]="(COUNT_BITS+1)'(34);"
to[texture_capacity]="(COUNT_BITS+1)'(33);"  # the unit holds one fragment fewer: the walker waits a cycle early
from[texture_bank_route]='wire [23:0] texel10 = tex_rd_texels[24*{py[1], px[0]} +: 24];'
to[texture_bank_route]='wire [23:0] texel10 = tex_rd_texels[24*{py[0], px[1]} +: 24];'  # the second column's texel from the wrong bank
from[texture_stall_ignored]='wire issue = head_valid && (!head_textured || tex_rd_ready);'
to[texture_stall_ignored]='wire issue = head_valid;'  # a read the texture memory refused counts as taken
from[texture_untextured_waits]='wire issue = head_valid && (!head_textured || tex_rd_ready);'
to[texture_untextured_waits]='wire issue = head_valid && tex_rd_ready;'  # untextured fragments wait for the memory too
file[texture_left_slots]=z_adder.sv
from[texture_left_slots]='.left_start({texture_record[1 + (15 + c)*TR +: TR], texture_record[1 + (9 + c)*TR +: TR]}),'
to[texture_left_slots]='.left_start({texture_record[1 + (9 + c)*TR +: TR], texture_record[1 + (15 + c)*TR +: TR]}),'  # S, T, Q left-edge slots swapped
# The texture sampler's address and filter stages: the directed texture frames alone must catch them.
for m in "${texture_sampler_mutants[@]}"; do
  params[$m]="-GSETUP_INTERVAL=4 -GTEXTURE=1"
  check[$m]=--directed-only
done
file[texture_clamp_below]=texture_address.sv
from[texture_clamp_below]="else if (index < 0) place = 10'd0;"
to[texture_clamp_below]="else if (index < 0) place = index[9:0] & last[9:0];"  # clamp wraps indices below 0 as repeat does
file[texture_blend_rounding]=texture_filter.sv
from[texture_blend_rounding]="{17'd0, upper} * {26'd0, fy} + 34'd32768;"
to[texture_blend_rounding]="{17'd0, upper} * {26'd0, fy};"  # the bilinear mean truncated, not rounded
# The pipelined setup unit and the record FIFO.
for m in setup_slot_counter setup_floor_correction setup_missing_step setup_credit_count setup_fifo_empty setup_edge_sign \
         setup_offscreen_rows; do
  params[$m]="-GSETUP_INTERVAL=2"
done
file[setup_slot_counter]=triangle_setup_pipelined.sv
from[setup_slot_counter]='localparam integer LAST_PHASE = I - 1;'
to[setup_slot_counter]='localparam integer LAST_PHASE = I;'  # the slot counter wraps one late
file[setup_floor_correction]=triangle_setup_pipelined.sv
from[setup_floor_correction]='!negative ? magnitude : remainder_nonzero ? ~magnitude : -magnitude;'
to[setup_floor_correction]='!negative ? magnitude : -magnitude;'  # no floor step for a remainder
file[setup_missing_step]=triangle_setup_pipelined.sv
from[setup_missing_step]='NUMER_STEPS - VW;'
to[setup_missing_step]='NUMER_STEPS - VW + 1;'  # one shift-add step of the numerators skipped
file[setup_edge_sign]=triangle_setup_pipelined.sv
from[setup_edge_sign]='(edge_step_index == EDGE_SKIP ? -e_term : e_term)'
to[setup_edge_sign]='e_term'  # the edge values' sign bits added instead of subtracted
file[setup_offscreen_rows]=triangle_setup.sv
from[setup_offscreen_rows]='wire offscreen = bx1_raw < 0 || by1_raw < 0 ||'
to[setup_offscreen_rows]='wire offscreen = bx1_raw < 0 ||'  # a box above the screen reported no_centre
file[setup_credit_count]=rastersim_core.sv
from[setup_credit_count]='credits_held_q < setup_fifo_depth_q;'
to[setup_credit_count]='credits_held_q <= setup_fifo_depth_q;'  # one record credit too many
# The depth output stage: the bias unit and the depth word's encoder (a biased profile's cosim frames:
# bias constants and slopes).
cosim_only_mutants depth_bias.sv "-GSETUP_INTERVAL=4 -GDEPTH_EXPONENT_BITS=3 -GDEPTH_BIAS=1" "${depth_mutants[@]}"
file[depth_float_mantissa]=depth_word.sv
file[depth_bias_low_carry]=z_adder.sv
from[depth_bias_shift]='wire signed [PB-1:0] product_floor = product_q >>> 4;'
to[depth_bias_shift]='wire signed [PB-1:0] product_floor = product_q >>> 3;'  # the slope factor read as s5.3
from[depth_bias_smaller_step]='always @(posedge clk) slope_q <= magnitude_x_q > magnitude_y_q ? magnitude_x_q : magnitude_y_q;'
to[depth_bias_smaller_step]='always @(posedge clk) slope_q <= magnitude_x_q > magnitude_y_q ? magnitude_y_q : magnitude_x_q;'  # the smaller step
from[depth_bias_slope_unsigned]="assign partial[i] = cfg_depth_bias_slope[i] ? -(slope_wide <<< i) : {PB{1'b0}};"
to[depth_bias_slope_unsigned]="assign partial[i] = cfg_depth_bias_slope[i] ? slope_wide <<< i : {PB{1'b0}};"  # a negative slope factor read unsigned: a large positive one
from[depth_bias_ready_early]='wire push = biased ? valid_q[STAGES-2] : in_valid;'
to[depth_bias_ready_early]='wire push = biased ? valid_q[STAGES-3] : in_valid;'  # the bias written a stage early: the walker loads a cycle early
from[depth_float_mantissa]='if (value[NM + e - 1]) encoded = {e[NE-1:0], value[e - 1 +: NM]};'
to[depth_float_mantissa]='if (value[NM + e - 1]) encoded = {e[NE-1:0], value[e +: NM]};'  # the mantissa one bit too high
from[depth_bias_low_carry]="{{(Z_REG_BITS+1-F){1'b0}}, low_carry_q};"
to[depth_bias_low_carry]="{(Z_REG_BITS+2-F){1'b0}};"  # the carry out of the low bits' sum dropped: the biased output an LSB low at times
file[setup_fifo_empty]=setup_fifo.sv
from[setup_fifo_empty]='assign empty = count_q == {COUNT_BITS{1'"'"'b0}};'
to[setup_fifo_empty]='assign empty = count_q <= {{(COUNT_BITS-1){1'"'"'b0}}, 1'"'"'b1};'  # one record looks like none

# Mutants that an assertion inside the units (rtl/rastersim_assert.vh, verilated with --assert) must
# catch: the assertion's name, which the simulator's message gives ("Assertion failed in SCOPE: NAME").
declare -A assertion
assertion[setup_credit_count]=credits_within_depth
assertion[walker_backpressure]=fragment_held

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
status=0
for m in "${mutants[@]}"; do
  [ -n "${file[$m]:-}" ] || { echo "unknown mutant $m"; exit 2; }
  dir="$work/$m"
  mkdir -p "$dir"
  cp -r "$root/rtl" "$dir/rtl"
  python3 - "$dir/rtl/${file[$m]}" "${from[$m]}" "${to[$m]}" <<'PY'
import sys
path, old, new = sys.argv[1:4]
text = open(path).read()
if text.count(old) != 1:
    sys.exit(f"mutation anchor found {text.count(old)} times in {path}: {old}")
open(path, "w").write(text.replace(old, new))
PY
  echo "mutant $m: ${file[$m]}: '${from[$m]}' -> '${to[$m]}'"
  # Verilate, then build; Verilator's runtime objects (verilated*.o: the same sources and flags for
  # every mutant) are compiled for the first mutant only and copied into the others, touched so
  # that make takes them as newer than the freshly generated makefile they depend on.
  if ! verilator --cc --exe -Wno-fatal -Wno-lint -Wno-style --x-assign unique --x-initial unique --assert \
      -I"$dir/rtl" "$dir"/rtl/*.sv "$root/testbench/rtl/rastersim_debug.sv" --top-module rastersim_top --prefix Vmutant -Mdir "$dir/obj" \
      -GWIDTH=64 -GHEIGHT=48 -GSUBPIXEL_BITS=4 -GZ_BITS=24 -GMAX_MEMORY_LATENCY=$max_latency ${params[$m]:-} --trace-fst \
      "$root/testbench/mutant_check.cpp" -o mutant_check \
      -CFLAGS "-std=gnu++17 -O1 -I$root -isystem $build/testbench" \
      -LDFLAGS "$build/testbench/librastersim_rtl.a $build/librastersim_model.a" > "$dir/build.log" 2>&1 \
     || ! { if compgen -G "$work/runtime/*.o" > /dev/null; then cp "$work"/runtime/* "$dir/obj/" && touch "$dir"/obj/verilated*.o; fi; } \
     || ! make -C "$dir/obj" -f Vmutant.mk -j 2 >> "$dir/build.log" 2>&1; then
    echo "mutant $m: build failed"; tail -20 "$dir/build.log"; status=1; continue
  fi
  if ! compgen -G "$work/runtime/*.o" > /dev/null; then
    mkdir -p "$work/runtime"
    cp "$dir"/obj/verilated*.o "$dir"/obj/verilated*.d "$work/runtime/"
  fi
  # The mutant's binary stays beside its replay files: the replay command it prints runs it there.
  replays="$build/rtl-mutants/$m"
  mkdir -p "$replays"
  cp "$dir/obj/mutant_check" "$replays/mutant_check"
  if "$replays/mutant_check" "$replays" "$max_latency" ${check[$m]:-} > "$dir/check.log"; then
    cat "$dir/check.log"
    # What cosim gives for a divergence: the replay reproduces it alone, and the waveform window
    # holds its cycle (the debug monitor's frame_cycle takes that value in the dump).
    sentence=$(grep '^first divergence: ' "$dir/check.log")
    cycle=$(sed -n 's/^waveform: .*divergence cycle \(-\?[0-9]*\)$/\1/p' "$dir/check.log")
    prefix="$replays/mutant_replay"
    if grep -q '^replay: none' "$dir/check.log"; then
      replayed="$sentence"  # a textured frame: no .tri replay (it would carry no texture)
    else
      read -r program _ prefix seed < <(sed -n 's/^replay: //p' "$dir/check.log")
      replayed=$("$program" --replay "$prefix" "$seed" | grep '^first divergence: ' || true)
    fi
    if [ -n "${assertion[$m]:-}" ] && ! grep -q "Assertion failed in .*${assertion[$m]}" "$dir/check.log"; then
      echo "mutant $m: caught, but not by the assertion ${assertion[$m]}"; status=1
    elif [ "$replayed" != "$sentence" ]; then
      echo "mutant $m: the replay gives '$replayed', not the catch's '$sentence'"; status=1
    elif ! python3 - "$prefix.vcd" "$cycle" "$prefix.vcd.gtkw" <<'PY'
import sys
path, cycle, save = sys.argv[1], int(sys.argv[2]), sys.argv[3]
ids, scope, values, time = {}, [], {}, 0
for line in open(path):
    w = line.split()
    if not w:
        continue
    if w[0] == "$scope":
        scope.append(w[2])
    elif w[0] == "$upscope":
        scope.pop()
    elif w[0] == "$var" and scope[-1:] == ["debug"] and w[4] == "frame_cycle":
        ids[w[3]] = True
    elif w[0][0] == "#":
        time = int(w[0][1:])
    elif w[0][0] == "b" and len(w) == 2 and w[1] in ids:
        values[int(w[0][1:], 2)] = time
if cycle >= 0 and cycle not in values:
    sys.exit(f"{path}: frame_cycle takes {min(values, default=None)}..{max(values, default=None)}, not {cycle}")
# The save file's marker "mismatch" sits on the divergence cycle's rising edge (frame_cycle turns
# cycle + 1 there).
lines = open(save).read().splitlines()
names = {l[len("[markername] ") + 1:]: ord(l[len("[markername] ")]) - ord("A") for l in lines if l.startswith("[markername] ")}
times = next(l for l in lines if l.startswith("*")).split()[2:]
if cycle >= 0 and ("mismatch" not in names or int(times[names["mismatch"]]) != values.get(cycle + 1)):
    sys.exit(f"{save}: no marker 'mismatch' at time {values.get(cycle + 1)}")
PY
    then
      echo "mutant $m: the waveform window or its save file misses the divergence cycle $cycle"; status=1
    else
      how="the replay reproduces it alone"
      grep -q '^replay: none' "$dir/check.log" && how="a textured frame, no .tri replay"
      echo "mutant $m: caught ($how; the waveform window holds cycle $cycle)"
    fi
  else
    cat "$dir/check.log"
    echo "mutant $m: NOT caught"; status=1
  fi
done
exit $status
