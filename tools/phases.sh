# Sourced by the README's commands: `phase NAME` ends the phase before it and
# starts NAME; `phases_done` ends the last and prints each phase's seconds,
# so a run's log says where its time went (tools/bare-machine.sh reads it).
phase_names=()
phase_seconds=()
phase_started=""
phase_now() { printf '%s' "${EPOCHREALTIME/,/.}"; }
phase_end() {
  [[ -z "$phase_started" ]] && return 0
  phase_seconds+=("$(awk -v a="$phase_started" -v b="$(phase_now)" 'BEGIN { printf "%.1f", b - a }')")
  phase_started=""
}
phase() {
  phase_end
  phase_names+=("$1")
  phase_started=$(phase_now)
  echo "== phase: $1"
}
phases_done() {
  phase_end
  local i
  echo "== phases (seconds):"
  for i in "${!phase_names[@]}"; do printf '== phase %-16s %8s s\n' "${phase_names[$i]}" "${phase_seconds[$i]}"; done
}
