#!/usr/bin/env bash
# DriftLab set-up on Debian 12: installs the packages it needs (skipping those
# present), builds, then runs one job.
#
#   bash packaging/bootstrap.sh main    the main job: a campaign into SQLite, its summary
#   bash packaging/bootstrap.sh test    every test (ctest, offscreen)
#   bash packaging/bootstrap.sh build   install and build only
#
# DRIFTLAB_BUILD_DIR overrides the build folder (default: build/).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${DRIFTLAB_BUILD_DIR:-$root/build}
job=${1:-main}

log() { printf '== %s\n' "$*" >&2; }

install_packages() {
    local missing=() package
    while read -r package; do
        [[ -z $package || $package == \#* ]] && continue
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'ok installed' || missing+=("$package")
    done <"$root/packaging/debian-packages.txt"
    if ((${#missing[@]} == 0)); then
        log "all Debian packages present"
        return
    fi
    local sudo=()
    ((EUID != 0)) && sudo=(sudo)
    log "installing ${missing[*]}"
    "${sudo[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

build_project() {
    log "building in $build"
    export CCACHE_DIR=${CCACHE_DIR:-$HOME/.cache/ccache}
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/dev/null
    # Two cores on the reference machine; more jobs only thrash memory.
    cmake --build "$build" --parallel "${DRIFTLAB_JOBS:-2}"
}

run_main_job() {
    local cli=$build/app/driftlab-cli out=$build/main-job
    rm -rf "$out" && mkdir -p "$out"
    log "main job: importing the example campaign into $out/driftlab.sqlite"
    local id
    id=$("$cli" import "$root/resources/examples/x-axis-moving-state" --db "$out/driftlab.sqlite")
    "$cli" info --db "$out/driftlab.sqlite" --campaign "$id"
    "$cli" export --db "$out/driftlab.sqlite" --campaign "$id" --out "$out/exported-bundle" >/dev/null
    log "campaign $id stored in $out/driftlab.sqlite and exported to $out/exported-bundle"
}

run_tests() {
    log "running the tests"
    cd "$build"
    QT_QPA_PLATFORM=offscreen ctest --output-on-failure --parallel "${DRIFTLAB_JOBS:-2}"
}

case $job in
    main) install_packages && build_project && run_main_job ;;
    test) install_packages && build_project && run_tests ;;
    build) install_packages && build_project ;;
    *) echo "usage: bash packaging/bootstrap.sh main|test|build" >&2; exit 2 ;;
esac
