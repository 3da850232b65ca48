# Sourced by the device scripts (tools/device_contact.sh, tools/device_surface.sh) that run ON
# the GPU machine with build-dev carried: sets root, bin, out, work (from WORK_NAME), table
# (from TABLE_NAME), py (a Python with numpy and h5py), the library path, prints the GPU
# into the table, and `want PART` (true when PART is among the script's arguments, or when
# there are none and PART is in DEFAULT_PARTS), and `parity NAME CASE NSTEPS [ARGS...]` (the state
# hashes of -cpu -threads:1, 2, 16 and -gpu, one line in the table).
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export LD_LIBRARY_PATH="$root/build-dev/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
bin="$root/build-dev/bin"
out="${OUT:-/tmp/seaspring_out}"
work="/tmp/$WORK_NAME"
mkdir -p "$out" "$work"
table="$out/$TABLE_NAME"
py=/usr/bin/python3
"$py" -c "import numpy, h5py" 2>/dev/null || py=/opt/torch/.venv/bin/python3
nvidia-smi --query-gpu=name --format=csv,noheader | tee -a "$table"
want() { local p; for p in "${parts[@]}"; do [[ $p == "$1" ]] && return 0; done; return 1; }
parity() {  # name case nsteps extra...
  local name=$1 kase=$2 n=$3; shift 3
  local h=()
  for b in "-cpu -threads:1" "-cpu -threads:2" "-cpu -threads:16" "-gpu"; do
    local log="$work/$name.${b//[ :]/_}.log"
    "$bin/seaspring" $b -overwrite -nsteps:"$n" -sv:none -progress:0 "$@" "$kase" "$work/o_$name" >"$log" 2>&1 ||
      { echo "FAILED $name $b"; tail -3 "$log"; }
    h+=("$(grep -o 'State hash: [0-9a-f]*' "$log" | cut -d' ' -f3)")
  done
  local same=yes
  for x in "${h[@]}"; do [[ "$x" == "${h[0]}" ]] || same=NO; done
  printf '%-24s cpu1=%s cpu2=%s cpu16=%s gpu=%s identical=%s\n' "$name" "${h[@]}" "$same" | tee -a "$table"
}
