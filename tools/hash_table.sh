#!/usr/bin/env bash
# State hashes (and gauge-file digests) of a fixed set of short runs that cover the physics
# families, solids, breakage and contact: the regression table for changes that must not change
# a result, and for CPU = GPU. Runs locally or on the GPU machine (build-dev carried).
# Usage: tools/hash_table.sh BIN_DIR OUT_TABLE "BACKEND FLAGS" [NAME_REGEX]
#   e.g. tools/hash_table.sh build/bin /tmp/cpu2.txt "-cpu -threads:2"
#        tools/hash_table.sh build-dev/bin /tmp/gpu.txt "-gpu"        (then diff the tables)
# The DualSPHysics 2D case comes from SHARED_CASES (default: build-dev/shared-cases if it has it,
# else ../shared/dualsphysics-cases).
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin=$1; table=$2; flags=$3; only=${4:-.}
shared=${SHARED_CASES:-}
if [[ -z $shared ]]; then
  shared=$root/build-dev/shared-cases
  [[ -f $shared/CaseDambreakVal2D_Def.xml ]] || shared=$root/../shared/dualsphysics-cases
fi
[[ -n ${LD_LIBRARY_PATH:-} || ! -d $root/build-dev/lib || $bin != *build-dev* ]] || export LD_LIBRARY_PATH=$root/build-dev/lib
work=$(mktemp -d /tmp/hashtable.XXXX)
: >"$table"
G="$bin/gencase"
gen() { "$G" "$@" >/dev/null 2>&1 || echo "gencase failed: $*"; }
run() { local name=$1 kase=$2 n=$3; shift 3
  [[ $name =~ $only ]] || return 0
  # shellcheck disable=SC2086
  "$bin/seaspring" $flags -nsteps:"$n" -sv:none -progress:0 "$@" "$kase" "$work/o_$name" >"$work/$name.log" 2>&1 ||
    { echo "FAILED $name"; tail -3 "$work/$name.log"; }
  local h g=""; h=$(grep -o 'State hash: [0-9a-f]*' "$work/$name.log" | cut -d' ' -f3)
  if [[ -d "$work/o_$name/gauges" ]]; then g=$(cat "$work/o_$name"/gauges/*.csv | md5sum | cut -c1-12); fi
  printf '%-30s %s %s\n' "$name" "$h" "$g" | tee -a "$table"; }
gen "$root/cases/dambreak3d/DamBreak3D_Def.xml" "$work/db3d"
gen "$shared/CaseDambreakVal2D_Def.xml" "$work/val2d" -dp:0.02
gen "$root/cases/hanging_beam/HangingBeam_Def.xml" "$work/beam" -dp:0.01
gen "$root/cases/hydrostatic_plate/HydrostaticPlate_Def.xml" "$work/plate" -dp:0.025
gen "$root/cases/dambreak_plate3d/DamBreakPlate3D_Def.xml" "$work/dbplate"
gen "$root/cases/breaking_bar/BreakingBar_Def.xml" "$work/bar"
gen "$root/cases/cantilever3d_tipload/CantileverTipLoad3D_Def.xml" "$work/tip2" -dp:0.002
gen "$root/tests/data/gauges/StillTank_Def.xml" "$work/gtank"
gen "$root/cases/antoci_gate2d/AntociGate2D_Def.xml" "$work/antoci" -dp:0.002
gen "$root/tests/data/phases/ContactBlocks2D_Def.xml" "$work/blocks"
sed 's|<parameters>|<parameters><parameter key="VcpmContact" value="1" /><parameter key="VcpmContactFriction" value="0.3" />|' \
  "$root/cases/pmma_collapse2d/PmmaCollapse2D_Def.xml" >"$work/PmmaC_Def.xml"
gen "$work/PmmaC_Def.xml" "$work/pmmac"
# The rows' bending (physics/vcpm_rows.h) is on by default with the surface correction: these two
# rows run without it.
norows='<parameters><parameter key="VcpmRowBending" value="0" />'
sed "s|<parameters>|$norows|" "$root/cases/breaking_bar/BreakingBar_Def.xml" >"$work/BarNoRows_Def.xml"
gen "$work/BarNoRows_Def.xml" "$work/barnorows"
sed "s|<parameters>|$norows|" "$root/cases/antoci_gate2d/AntociGate2D_Def.xml" >"$work/AntociNoRows_Def.xml"
gen "$work/AntociNoRows_Def.xml" "$work/antocinorows" -dp:0.002
# h = 2 dp with cells of h/2 = dp: the grid moved half a spacing off the fluid's lattice
# (solver/grid_origin.h); the other rows' cells are not a whole number of spacings.
sed 's|<coefh value="1.0"|<hdp value="2"|' "$root/cases/dambreak3d/DamBreak3D_Def.xml" >"$work/DbHdp2_Def.xml"
gen "$work/DbHdp2_Def.xml" "$work/dbhdp2" -dp:0.03
run db3d_sym_wend_art_ddt3 "$work/db3d" 40 -symplectic -wendland -viscoart:0.1 -ddt:3
run db3d_verlet_cubic_lam_ddt1 "$work/db3d" 40 -verlet -cubic -viscolam:1e-6 -ddt:1
run db3d_sym_wend_sps_ddt2 "$work/db3d" 40 -symplectic -wendland -viscolamsps:1e-6 -ddt:2
run db3d_cells2h "$work/db3d" 40 -cellmode:full
run db3d_cells_h "$work/db3d" 40 -cellmode:h
run db3d_cells_third "$work/db3d" 40 -cellmode:third
run val2d_sym_wend_art_ddt3 "$work/val2d" 300 -symplectic -ddt:3
run val2d_verlet_cubic_sps_ddt0 "$work/val2d" 300 -verlet -cubic -viscolamsps:1e-6 -ddt:0
run gauges_val2d_swl "$work/val2d" 600
run gauges_tank "$work/gtank" 300
run gauges_antoci "$work/antoci" 400
run beam3d_solid_only "$work/beam" 3000
run tipload3d_pointloads "$work/tip2" 3000
run plate2d_midpoint "$work/plate" 400
run plate2d_seedscheme "$work/plate" 400 -vcpmcoupling:1
run bar_breaking "$work/bar" 4000
run dbplate3d_breaking "$work/dbplate" 1800
run contact_blocks2d "$work/blocks" 3000
run pmma2d_contact "$work/pmmac" 800
run bar_breaking_norows "$work/barnorows" 4000
run gauges_antoci_norows "$work/antocinorows" 400
run db3d_hdp2_centred "$work/dbhdp2" 40 -symplectic -wendland -viscoart:0.1 -ddt:3
rm -rf "$work"
