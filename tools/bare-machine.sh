#!/usr/bin/env bash
# The README's commands as a new user meets them: a fresh clone of this
# checkout's HEAD, every cache empty (XDG_CACHE_HOME, RAYSPEC_CACHE_DIR,
# MESA_SHADER_CACHE_DIR, CCACHE_DIR and HOME are new folders), then the
# command, timed per phase and per ctest test.
#
#   tools/bare-machine.sh [--chroot] [--command test|run] [--out FILE] [--keep]
#     --chroot     a new Debian 12 (debootstrap minbase) with nothing installed:
#                  the packages are part of the time (root; needs Debian's mirror)
#     --command    test: bash tools/test.sh (default); full: bash tools/test.sh --full
#                  (what CI runs); run: bash tools/run-suite.sh
#     --out FILE   the table (default references/runs/bare-machine-COMMAND.txt)
#     --keep       keep the scratch folder (printed; command.log is the whole
#                  output) instead of removing it
#
# Without --chroot the packages this machine has are used as they are; the
# table says which. A folder ../shared beside the checkout (CI has one) is
# copied beside the clone as it is; rayspec itself reads nothing there.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
chroot_mode=0
command=test
out=""
keep=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    --chroot) chroot_mode=1 ;;
    --command) command=$2; shift ;;
    --out) out=$2; shift ;;
    --keep) keep=1 ;;
    *) echo "bare-machine: unknown argument $1" >&2; exit 2 ;;
  esac
  shift
done
case "$command" in
  test) script=tools/test.sh ;;
  full) script="tools/test.sh --full" ;;
  run) script=tools/run-suite.sh ;;
  *) echo "bare-machine: --command must be test, full or run, not $command" >&2; exit 2 ;;
esac
out=${out:-references/runs/bare-machine-$command.txt}
scratch=$(mktemp -d /var/tmp/rayspec-bare.XXXXXX)
mounted=()
cleanup() {
  local m
  for m in "${mounted[@]}"; do umount -R "$m" || true; done
  if [[ $keep -eq 1 ]]; then echo "bare-machine: kept $scratch"; else rm -rf "$scratch"; fi
}
trap cleanup EXIT

# The machine: this one (packages as they are) or a new Debian 12 in $scratch/root.
if [[ $chroot_mode -eq 1 ]]; then
  [[ $(id -u) -eq 0 ]] || { echo "bare-machine: --chroot needs root" >&2; exit 2; }
  started=$EPOCHREALTIME
  debootstrap --variant=minbase bookworm "$scratch/root" http://deb.debian.org/debian >"$scratch/debootstrap.log"
  debootstrap_seconds=$(awk -v a="$started" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.0f", b - a }')
  # Recursive binds: /dev/pts and /dev/shm as a real machine has them
  # (cli/isolation opens a pseudo-terminal).
  for m in proc dev sys; do
    mount --rbind "/$m" "$scratch/root/$m" && mount --make-rslave "$scratch/root/$m" && mounted+=("$scratch/root/$m")
  done
  cp /etc/resolv.conf "$scratch/root/etc/resolv.conf"
  base=$scratch/root/work
  inside=/work
else
  base=$scratch/work
  inside=$base
fi
mkdir -p "$base/home"
git clone --quiet "$root" "$base/rayspec"
if [[ -d ../shared ]]; then cp -r ../shared "$base/shared"; fi
revision=$(git -C "$base/rayspec" rev-parse --short HEAD)

# The command, with every cache a new folder.
# RAYSPEC_CACHE_DIR, MESA_SHADER_CACHE_DIR and CCACHE_DIR are unset, as a new
# user has them: their defaults lie in the new HOME and XDG_CACHE_HOME.
caches=(HOME=$inside/home XDG_CACHE_HOME=$inside/home/.cache)
run_inside=(env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin "${caches[@]}"
            bash -c "cd $inside/rayspec && bash $script")
[[ $chroot_mode -eq 1 ]] && run_inside=(chroot "$scratch/root" "${run_inside[@]}")
log=$scratch/command.log
started=$EPOCHREALTIME
status=0
"${run_inside[@]}" >"$log" 2>&1 || status=$?
total=$(awk -v a="$started" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.0f", b - a }')

# The table: the machine, each phase, the ctest totals and its 10 longest tests.
{
  echo "# bash $script on a bare machine ($(date -u '+%Y-%m-%d %H:%M UTC'), rayspec $revision)"
  echo "machine: $(nproc) cores, $(awk '/MemTotal/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo)," \
    "$(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo)"
  if [[ $chroot_mode -eq 1 ]]; then
    echo "packages: none (debootstrap --variant=minbase bookworm, ${debootstrap_seconds} s, not counted below)"
  else
    echo "packages: this machine's, already installed (setup below is only the check)"
  fi
  echo "caches: all empty (HOME, XDG_CACHE_HOME, RAYSPEC_CACHE_DIR, MESA_SHADER_CACHE_DIR, CCACHE_DIR)"
  echo "exit status: $status"
  echo
  printf '| %-16s | %8s |\n' phase seconds '----------------' '--------'
  grep '^== phase [^:(]' "$log" | awk '{ printf "| %-16s | %8s |\n", $3, $4 }'
  printf '| %-16s | %8s |\n' "all" "$total"
  if grep -q 'tests passed\|tests failed' "$log"; then
    echo
    grep -E 'tests (passed|failed)|Total Test time' "$log"
    echo
    echo "The 10 longest tests:"
    # "  3/241 Test  #57: case/culling ......   Passed   12.34 sec"
    awk '/Test +#[0-9]+: / && $NF == "sec" {
           for (i = 1; i < NF; i++) if ($i ~ /^#[0-9]+:$/) name = $(i + 1)
           status = $(NF - 2); gsub(/[.*]/, "", status)
           print $(NF - 1), name, status }' "$log" |
      sort -rn | head -10 | awk '{ printf "| %-44s | %8.1f s | %s\n", $2, $1, $3 }'
  fi
} | tee "$out"
exit "$status"
