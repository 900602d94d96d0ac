#!/usr/bin/env bash
# Installs the Debian packages the toolkit builds, tests, packages and
# benchmarks with: setup-deps.sh [build|test|deb|bench]. `make demo` needs
# only the build tier.
# Idempotent: packages already installed are skipped, and apt-get runs only
# when something is missing. Uses sudo when not root.
set -euo pipefail

# Build and runtime: compiler, CMake, the libraries every tool links; and
# python3, whose json module examples/demo.sh (`make demo`) and the other
# examples format the tools' records with (a bare Debian has none).
build_pkgs=(g++ cmake make pkg-config libcli11-dev libgmp-dev libeigen3-dev
            libfmt-dev nlohmann-json3-dev libprimesieve-dev libfftw3-dev libpolyclipping-dev
            libboost-math-dev scdoc python3)
# Tests: unit tests, CLI tests, the PARI/GP and ezdxf oracles, sanitizer runtime.
# linuxcnc-uspace ships rs274, LinuxCNC's own interpreter: the oracle for every G-code program.
# ccache: the builds reuse earlier compiles. dpkg-dev, file and man-db let
# test/bats/toolkit_deb.bats build and check the package; it runs lintian
# only where the deb tier installed it (~130 packages, minutes of apt).
# clang-format: the source_format test checks the layout .clang-format sets.
test_pkgs=(libgtest-dev bats bats-assert bats-support pari-gp python3 python3-ezdxf python3-scipy parallel fuzzylite
           linuxcnc-uspace ccache dpkg-dev file man-db clang-format)
# The Debian package (`make deb`): dpkg-shlibdeps and dpkg-deb, file for
# CPack's stripping, lintian to check the result, man to check the pages.
deb_pkgs=(dpkg-dev file lintian man-db)
# Benchmarks: peers timed in the same run (never runtime dependencies).
bench_pkgs=(libflint-dev primesieve libfuzzylite-dev libgsl-dev libboost-dev)

want=("${build_pkgs[@]}")
case "${1:-build}" in
  build) ;;
  test)  want+=("${test_pkgs[@]}") ;;
  deb)   want+=("${deb_pkgs[@]}") ;;
  bench) want+=("${test_pkgs[@]}" "${bench_pkgs[@]}") ;;
  *) echo "usage: $0 [build|test|deb|bench]" >&2; exit 2 ;;
esac

missing=()
for p in "${want[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup-deps: installing ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
