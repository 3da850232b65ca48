#!/usr/bin/env bash
# Runs ON the GPU machine (device tool) with build-dev carried: final state hashes of
# -cpu -threads:1, -cpu -threads:2 and -gpu on the small coupled cases that exercise the skin
# (moving boundaries and solids kept in their cells between sorts, a thin skin that sorts
# often), the hydrodynamic force inside the force launch (SPS with a wetted solid) and the
# dry-wall flags: Antoci gate 2D (symplectic, SPS, VCPM gate) and FlexStruc Liao 2D (Verlet,
# moving gate, VCPM plate).
set -u
export LD_LIBRARY_PATH=$PWD/build-dev/lib
b=${SS_BIN:-build-dev/bin}; w=/tmp/wp; mkdir -p $w
nvidia-smi --query-gpu=name --format=csv,noheader
$b/gencase cases/antoci_gate2d/AntociGate2D_Def.xml $w/ant >/dev/null
$b/gencase build-dev/shared-cases/flexstruc/CaseDambreak2D_FSI_Def.xml $w/liao >/dev/null 2>&1
row() {  # name case args...
  local name=$1 c=$2; shift 2; local h=() s=""
  for be in "-cpu -threads:1" "-cpu -threads:2" "-gpu"; do
    # shellcheck disable=SC2086
    $b/seaspring -overwrite $be -sv:none -progress:0 "$@" $w/$c $w/o_$name > $w/$name.log 2>&1 || tail -3 $w/$name.log
    h+=("$(grep -o 'State hash: [0-9a-f]*' $w/$name.log | cut -d' ' -f3)")
    s=$(grep -o 'sorted at [0-9]* of [0-9]* divides' $w/$name.log)
  done
  local same=yes; for x in "${h[@]}"; do [[ $x == "${h[0]}" ]] || same=NO; done
  printf '%-22s cpu1=%s cpu2=%s gpu=%s identical=%s (%s)\n' "$name" "${h[@]}" "$same" "$s"
}
row antoci_sps_solid ant -nsteps:600
row antoci_thin_skin ant -nsteps:600 -skin:0.002
row antoci_no_skin ant -nsteps:300 -skin:0
row liao_moving_solid liao -nsteps:1500
row liao_thin_skin liao -nsteps:1500 -skin:0.002
