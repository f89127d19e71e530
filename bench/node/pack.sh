#!/usr/bin/env bash
# pack.sh -- what a scaling run needs on a node that reaches no package registry, in one folder:
# LIGGGHTS and an Open MPI runtime from this machine's Debian packages, demcal's binaries, and
# the shared libraries all of them load (glibc, libstdc++ and libgcc excepted: a node has its
# own, as new or newer). bench/node/run.sh unpacks and uses it (bench/README.md, "On a node").
#
# usage (repository root, after `apt-get install liggghts` and a Release build):
#   bash bench/node/pack.sh [OUTDIR=.devcarry] [BUILD_DIR=build]
# writes OUTDIR/bundle.tgz (≈ 30 MB). Keep OUTDIR out of git (.git/info/exclude) and carry it.
set -euo pipefail
out=${1:-.devcarry}
build=${2:-build}
die() { echo "pack.sh: $*" >&2; exit 1; }
for f in "$build/apps/demcal" "$build/bench/demcal_bench"; do [[ -x $f ]] || die "$f missing: build first"; done
for f in liggghts mpirun orted; do command -v $f > /dev/null || die "$f not found: apt-get install liggghts"; done
lib=/usr/lib/x86_64-linux-gnu
[[ -d $lib/openmpi && -d $lib/pmix2 ]] || die "$lib/openmpi or pmix2 missing (Debian 12 Open MPI layout expected)"

stage=$(mktemp -d); trap 'rm -rf "$stage"' EXIT
root=$stage/bundle
mkdir -p "$root"/usr/bin "$root/usr/lib/x86_64-linux-gnu" "$root"/etc "$root"/usr/share "$root"/demcal/lib
# Open MPI's launcher and daemon, its plugins (openmpi/, pmix2/) and configuration.
for b in liggghts mpirun mpiexec orterun orted; do cp -L "$(command -v $b)" "$root/usr/bin/$b"; done
cp -a "$lib/openmpi" "$lib/pmix2" "$root/usr/lib/x86_64-linux-gnu/"
cp -a /usr/share/openmpi "$root/usr/share/"
cp -a /etc/openmpi "$root/etc/"
system_lib() {
  case $(basename "$1") in
    libc.so*|libm.so*|libpthread.so*|libdl.so*|librt.so*|ld-linux*|libstdc++*|libgcc_s*) return 0 ;;
  esac
  return 1
}
deps() { ldd "$@" 2>/dev/null | awk '/=> \// { print $3 }' | sort -u; }
plugins=$(find "$lib/openmpi" "$lib/pmix2" -name '*.so*' -type f)
# shellcheck disable=SC2086  # word splitting of the plugin list intended
for l in $(deps "$root"/usr/bin/liggghts "$root"/usr/bin/orted "$root"/usr/bin/mpirun $plugins); do
  system_lib "$l" && continue
  case $l in "$lib"/openmpi/*|"$lib"/pmix2/*) continue ;; esac
  cp -L "$l" "$root/usr/lib/x86_64-linux-gnu/"
done
cp "$build/apps/demcal" "$build/bench/demcal_bench" "$root/demcal/"
for l in $(deps "$build/apps/demcal" "$build/bench/demcal_bench"); do
  system_lib "$l" || cp -L "$l" "$root/demcal/lib/"
done
git rev-parse HEAD > "$root/demcal/commit" 2>/dev/null || echo unknown > "$root/demcal/commit"
mkdir -p "$out"
tar czf "$out/bundle.tgz" -C "$stage" bundle
echo "pack.sh: $(du -h "$out/bundle.tgz" | cut -f1) in $out/bundle.tgz (demcal $(cut -c1-7 "$root/demcal/commit"))"
