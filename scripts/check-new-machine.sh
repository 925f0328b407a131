#!/usr/bin/env bash
# Reruns the README's quick start the way a new machine would: purges every Debian package
# installed here that the machine image's package list does not name, clones this
# repository's committed state into a fresh folder, and runs `make render` then `make test`
# there, printing what it purged and how long each step took. Packages installed by hand
# can then no longer hide a missing install step in scripts/install-deps.sh.
#
#   sudo scripts/check-new-machine.sh --image-list PACKAGES.txt [--yes] [--keep]
#
# PACKAGES.txt: the image's packages, one per line, either a bare name or the
# "apt<TAB>name<TAB>version" lines of the workplace's package lists ('#' starts a comment).
# Without --yes it prints what it would purge and stops. --keep leaves the clone in place.
set -euo pipefail

image_list=${VCT_IMAGE_PACKAGES:-}
yes=0
keep=0
while [ $# -gt 0 ]; do
  case "$1" in
    --image-list) image_list=$2; shift 2 ;;
    --yes) yes=1; shift ;;
    --keep) keep=1; shift ;;
    -h|--help) sed -n 2,14p "$0"; exit 0 ;;
    *) echo "check-new-machine: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
if [ -z "$image_list" ] && [ -f /work/.library/env/packages/installed-cpp.txt ]; then
  image_list=/work/.library/env/packages/installed-cpp.txt
fi
if [ -z "$image_list" ] || [ ! -f "$image_list" ]; then
  echo "check-new-machine: --image-list FILE (the machine image's package list) is required" >&2
  exit 2
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
repo=$(cd "$(dirname "$0")/.." && pwd)

# Installed minus the image's list: what a new machine would not have.
image=$(mktemp)
installed=$(mktemp)
trap 'rm -f "$image" "$installed"' EXIT
awk -F'\t' '/^#/ {next} NF >= 2 && $1 == "apt" {print $2; next} NF == 1 && $1 != "" {print $1}' "$image_list" |
  sed 's/:.*//' | sort -u >"$image"
dpkg-query -W -f='${db:Status-Abbrev} ${Package}\n' | awk '$1 ~ /^ii/ {print $2}' | sed 's/:.*//' | sort -u >"$installed"
mapfile -t extra < <(comm -23 "$installed" "$image")
echo "check-new-machine: $(wc -l <"$installed") packages installed, $(wc -l <"$image") in the image's list, ${#extra[@]} to purge"
if [ ${#extra[@]} -gt 0 ]; then
  printf '  %s\n' "${extra[@]}" | head -200
  if [ "$yes" -ne 1 ]; then
    echo "check-new-machine: rerun with --yes to purge them and run the quick start"
    exit 0
  fi
  start=$(date +%s)
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get purge -y -qq "${extra[@]}" >/dev/null
  echo "check-new-machine: purged ${#extra[@]} packages in $(( $(date +%s) - start )) s"
elif [ "$yes" -ne 1 ]; then
  echo "check-new-machine: nothing to purge; rerun with --yes to run the quick start"
  exit 0
fi

clone=$(mktemp -d /tmp/vct-new-machine.XXXXXX)
git clone -q "$repo" "$clone"
echo "check-new-machine: cloned $(git -C "$clone" rev-parse --short HEAD) into $clone"
cd "$clone"
step() {
  local name=$1; shift
  local start; start=$(date +%s)
  if "$@" >"$clone/$name.log" 2>&1; then
    echo "check-new-machine: '$*' passed in $(( $(date +%s) - start )) s (log: $clone/$name.log)"
  else
    echo "check-new-machine: '$*' FAILED after $(( $(date +%s) - start )) s; last lines of $clone/$name.log:"
    tail -30 "$clone/$name.log"
    exit 1
  fi
}
step render make render
ls -l out/default.png out/default_ao.png out/default.json
step test make test
grep -E "tests passed|tests failed" "$clone/test.log" | tail -1
if [ "$keep" -ne 1 ]; then rm -rf "$clone"; fi
echo "check-new-machine: the quick start passes on a machine with only the image's packages"
