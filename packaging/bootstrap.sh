#!/usr/bin/env bash
# DriftLab set-up on Debian 12: installs the packages it needs (skipping those
# present), builds, then runs one job.
#
#   bash packaging/bootstrap.sh main    the main job: procedures run on the simulated rig, campaigns stored, modelled, compared, diagnosed,
#                                       compensated and pushed to a simulated controller
#   bash packaging/bootstrap.sh test    the tests (ctest, offscreen), without the validation suites
#   bash packaging/bootstrap.sh validate  the validation suites too, the benchmark, then docs/validation.md
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
    # Share the cache between build folders and work trees.
    export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(dirname "$root")} CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-true}
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/dev/null
    # Two cores on the reference machine; more jobs only thrash memory.
    cmake --build "$build" --parallel "${DRIFTLAB_JOBS:-2}"
}

# Starts `controller-sim` on a free port, pushes S1's table to it from the
# store, lists the push history and stops the simulator (also when a step fails).
push_to_simulated_controller() {
    local cli=$1 out=$2 id=$3 sim_pid port=""
    "$cli" controller-sim --port 0 >"$out/controller-sim.out" 2>"$out/controller-sim.err" &
    sim_pid=$!
    # errexit leaves the script from inside this function: stop the simulator on exit too.
    trap "kill $sim_pid 2>/dev/null || true" EXIT
    for _ in $(seq 100); do
        port=$(sed -n 's#.*modbus://127\.0\.0\.1:\([0-9]*\).*#\1#p' "$out/controller-sim.out")
        [[ -n $port ]] && break
        kill -0 "$sim_pid" 2>/dev/null || break
        sleep 0.1
    done
    if [[ -z $port ]]; then
        log "the simulated controller did not start: $(cat "$out/controller-sim.err")"; return 1
    fi
    "$cli" compensate --db "$out/driftlab.sqlite" --campaign "$id" --run S1 --spacing 30 \
        --push "modbus://127.0.0.1:$port" --max-change-um 50
    "$cli" pushes --db "$out/driftlab.sqlite" --campaign "$id"
    log "main job 14/18: live thermal compensation: heat-transfer fitted on S1, S3 replayed as live data, every update written to the controller's live-offset registers between cuts, scored on S3's measured thermal error"
    "$cli" live --db "$out/driftlab.sqlite" --campaign "$id" --run S3 --train S1 \
        --push "modbus://127.0.0.1:$port" >"$out/live.txt"
    tail -n 3 "$out/live.txt"
    kill -TERM "$sim_pid" && wait "$sim_pid"
    trap - EXIT
    cat "$out/controller-sim.err" >&2
}

run_main_job() {
    local cli=$build/app/driftlab-cli out=$build/main-job
    rm -rf "$out" && mkdir -p "$out"
    local procedures=$root/resources/procedures logged
    log "main job 1/18: acquisition: the ISO 230-2 positioning procedure (irregular targets, 5 bidirectional cycles) run on the simulated rig and logged live into $out/driftlab.sqlite; its evaluation"
    logged=$("$cli" run --procedure "$procedures/iso230-2-x-axis.json" --rig sim --db "$out/driftlab.sqlite")
    "$cli" iso230-2 --db "$out/driftlab.sqlite" --campaign "$logged" | tail -n 4
    log "main job 2/18: acquisition: ISO 230-3 thermal distortion of the moving axis (warm-up until two passes agree within 1 µm, then cool-down) logged live; its drift evaluation and a model fitted on it"
    logged=$("$cli" run --procedure "$procedures/iso230-3-x-axis.json" --rig sim --db "$out/driftlab.sqlite")
    "$cli" iso230-3 --db "$out/driftlab.sqlite" --campaign "$logged" | tail -n 3
    "$cli" fit --db "$out/driftlab.sqlite" --campaign "$logged" --model heat-transfer | sed -n '/score on/,$p'
    log "main job 3/18: simulating a five-state campaign on the built-in rig, with six ISO 230-3 spindle runs of different speed programmes"
    "$cli" simulate --out "$out/campaign" --plots "$out/plots" --spindle-runs 6 --seed 1 >/dev/null
    log "main job 4/18: zipping the bundle as a user mails it, importing the zip into the same store (checked, then one transaction)"
    (cd "$out" && zip -qr campaign.zip campaign)
    local id
    id=$("$cli" import "$out/campaign.zip" --db "$out/driftlab.sqlite")
    "$cli" info --db "$out/driftlab.sqlite" --campaign "$id"
    if "$cli" import "$out/campaign" --db "$out/driftlab.sqlite" >/dev/null 2>"$out/again.err"; then
        log "the same campaign imported twice went unnoticed"; return 1
    fi
    log "the unzipped folder is the same content: $(tail -n 1 "$out/again.err")"
    log "sensor self-diagnosis of every logged channel (open/short, frozen, spikes, rate of change)"
    "$cli" health --db "$out/driftlab.sqlite" --campaign "$id"
    log "main job 5/18: heat-transfer model identified on S1, tested on S2-S5 (stored in the database)"
    "$cli" fit --db "$out/driftlab.sqlite" --campaign "$id" --model heat-transfer --train S1
    log "main job 6/18: the same with the best temperature regression (mlr); below each score, the channels where S2-S5 leave S1's temperature rises: a regression extrapolates there, the physics model holds"
    "$cli" fit --db "$out/driftlab.sqlite" --campaign "$id" --model mlr --train S1
    log "main job 7/18: every model, fitted on each state and scored on every other"
    "$cli" compare --db "$out/driftlab.sqlite" --campaign "$id"
    log "main job 8/18: a second campaign with two effects hidden in the simulated rig (structure growth lagging its sensor, forced convection), run through the procedure engine (five moving states) and logged live; the diagnosis must find both, in order"
    local hidden
    hidden=$("$cli" run --procedure "$procedures/moving-states-s1-s5.json" --rig sim \
        --effect forced_convection=0.05 --effect frame_growth=3 --db "$out/driftlab.sqlite" \
        2>"$out/hidden-run.err")
    "$cli" diagnose --db "$out/driftlab.sqlite" --campaign "$hidden" --plots "$out/plots/diagnosis"
    log "main job 9/18: ISO 230-2 acceptance of S1's interferometer cycles against resources/examples/x-axis-acceptance.json: readings at 20 °C, uncertainty budget, PASS / FAIL / NOT PROVEN by ISO 14253-1 (a moving state: its thermal drift inflates R, as the warning says)"
    "$cli" iso230-2 --db "$out/driftlab.sqlite" --campaign "$id" --run S1 \
        --spec "$root/resources/examples/x-axis-acceptance.json"
    log "main job 10/18: ISO 230-3 thermal drift of S1's targets and the spindle run's probes: maximum, when, time to stabilise"
    "$cli" iso230-3 --db "$out/driftlab.sqlite" --campaign "$id" --run S1
    "$cli" iso230-3 --db "$out/driftlab.sqlite" --campaign "$id" --run SP1
    log "the spindle's z drift lags every sensor: fit --model auto chooses family and inputs on SP1-SP3 alone, scored on SP4-SP6 (next to it, the static regression mlr)"
    "$cli" fit --db "$out/driftlab.sqlite" --campaign "$id" --model auto --target D_z \
        --train SP1,SP2,SP3 --test SP4,SP5,SP6
    "$cli" fit --db "$out/driftlab.sqlite" --campaign "$id" --model mlr --target D_z \
        --train SP1,SP2,SP3 --test SP4,SP5,SP6 | sed -n '/score on/,$p'
    log "main job 11/18: compensation tables from S1's interferometer readings for LinuxCNC and Sinumerik, in $out/compensation/"
    mkdir -p "$out/compensation"
    "$cli" compensate --db "$out/driftlab.sqlite" --campaign "$id" --run S1 --format linuxcnc \
        --spacing 30 --out "$out/compensation/x.comp"
    "$cli" compensate --db "$out/driftlab.sqlite" --campaign "$id" --run S1 --format sinumerik \
        --spacing 30 --out "$out/compensation/x_eec.ini" >/dev/null
    log "main job 12/18: the same table warm: plus the heat-transfer model's thermal error (fitted on S1) at S3 after 2 h, and its straight line for Sinumerik's temperature compensation"
    "$cli" compensate --db "$out/driftlab.sqlite" --campaign "$id" --run S1 --format linuxcnc \
        --spacing 30 --max-value-um 200 --model heat-transfer --train S1 --at S3@7200 \
        --out "$out/compensation/x_warm.comp" | head -n 2
    "$cli" compensate --db "$out/driftlab.sqlite" --campaign "$id" --run S1 --format sinumerik-temp \
        --model heat-transfer --train S1 --at S3@7200 --out "$out/compensation/x_temp_comp.spf"
    log "main job 13/18: S1's table pushed over Modbus TCP to the simulated controller (staged, checksummed, applied, read back), then the push history"
    push_to_simulated_controller "$cli" "$out" "$id"
    "$cli" export --db "$out/driftlab.sqlite" --campaign "$id" --out "$out/exported" >/dev/null
    mkdir -p "$out/report"
    log "main job 15/18: the acceptance report of the hidden-effect campaign (ISO 230-2 of S1, ISO 230-3, cross-state matrix, diagnosis, compensation before/after) as PDF with vector plots, HTML and CSV in $out/report/"
    "$cli" report --db "$out/driftlab.sqlite" --campaign "$hidden" --run S1 --operator "DriftLab main job" \
        --pdf "$out/report/acceptance-report.pdf" --html "$out/report/html" --csv "$out/report/csv" \
        --json >"$out/report/report.json"
    log "report: $out/report/acceptance-report.pdf ($(grep -o '"pages": *[0-9]*' "$out/report/report.json" | grep -o '[0-9]*$') pages)"
    log "main job 16/18: batch analysis of the bundle, its zip and every campaign of the store, two at a time in separate processes, one JSON line each in $out/batch.jsonl"
    "$cli" batch "$out/campaign" "$out/campaign.zip" "$out/driftlab.sqlite" -j 2 \
        --what info,iso230-2,fit >"$out/batch.jsonl"
    python3 -c 'import json, sys
for line in open(sys.argv[1]):
    r = json.loads(line)
    fit = (r.get("fit") or {}).get("score") or {}
    iso = r.get("iso230_2") or {}
    print("  %-46s %-5s ISO 230-2 A %6s µm  heat-transfer RMS %5s µm (%s)" % (r["item"][-46:],
          "ok" if r["ok"] else "FAIL", "%.2f" % iso["A"] if "A" in iso else "-",
          "%.2f" % fit["rms_um"] if "rms_um" in fit else "-", (r.get("fit") or {}).get("score_kind", "skipped")))' "$out/batch.jsonl"
    log "main job 17/18: the Debian package (cpack) in $out/deb/, and its control fields"
    (cd "$build" && cpack -G DEB -B "$out/deb" >/dev/null)
    dpkg-deb -f "$out"/deb/driftlab_*.deb Package Version Depends | cut -c 1-200
    log "main job 18/18: the desktop application (driftlab) under Xvfb at 1280x800: the demo played through the window (run on the simulated rig, fit, compare, diagnose), a screenshot of every page in $out/gui/shots"
    bash "$root/tests/ui/xvfb_demo.sh" "$build/app/driftlab" "$out/gui"
    log "done: bundle $out/campaign (and .zip), database $out/driftlab.sqlite, exported back to $out/exported, plots in $out/plots, GUI screenshots in $out/gui/shots, Debian package in $out/deb"
    log "the acceptance report is $out/report/acceptance-report.pdf (HTML: $out/report/html/index.html, CSV: $out/report/csv/)"
}

run_tests() {
    log "running the tests (the validation suites: bootstrap.sh validate)"
    cd "$build"
    QT_QPA_PLATFORM=offscreen ctest --output-on-failure --parallel "${DRIFTLAB_JOBS:-2}" -LE validation
}

# Every test, the hidden-effect suites of label `validation` included, and the
# benchmark; their records become docs/validation.md.
run_validation() {
    log "running every test, the validation suites included"
    (cd "$build" && QT_QPA_PLATFORM=offscreen ctest --output-on-failure --parallel "${DRIFTLAB_JOBS:-2}")
    log "benchmark: $build/bench.json"
    "$build/bench/driftlab-bench" --json --repeat 3 >"$build/bench.json"
    /usr/bin/python3 "$root/tests/validation/validation_page.py" --build "$build" --bench "$build/bench.json" \
        >"$root/docs/validation.md"
    log "docs/validation.md regenerated"
}

case $job in
    main) install_packages && build_project && run_main_job ;;
    test) install_packages && build_project && run_tests ;;
    validate) install_packages && build_project && run_validation ;;
    build) install_packages && build_project ;;
    *) echo "usage: bash packaging/bootstrap.sh main|test|validate|build" >&2; exit 2 ;;
esac
