#!/usr/bin/env bash
# The Debian package, built and checked as a lab would get it:
#   1. `cpack -G DEB` from the build folder into a temporary folder;
#   2. its control fields and contents (dpkg-deb -I / -c): both executables,
#      the desktop entry, the AppStream metadata, the icons, the shipped
#      procedures, Depends naming Qt and the QSQLITE driver;
#   3. the desktop entry (desktop-file-validate) and the AppStream metadata
#      (appstreamcli validate --no-net) as installed, the CLI run from the
#      unpacked tree;
#   4. as root only (else exit 77, reported SKIPPED): `dpkg -i`, the installed
#      driftlab-cli (--version, simulate, info, import into SQLite, a shipped
#      procedure run on the simulated rig) and driftlab (--help, a start under
#      Xvfb that saves its pages), then `dpkg -r driftlab`, also when a step
#      failed.
# A driftlab package installed before (a previous run that was killed) is
# removed first. Usage: deb_package_test.sh BUILD_DIR VERSION
set -euo pipefail

build=$1 version=$2
readonly skipped=77 app_id=org.driftlab.DriftLab

# The steps taken are printed only when one fails: a passing test prints nothing.
steps=()
fail() {
    printf '== %s\n' "${steps[@]}" >&2
    echo "FAIL: $*" >&2
    exit 1
}
step() { steps+=("$*"); }

work=$(mktemp -d /tmp/driftlab-deb-test.XXXXXX)
installed_by_us=false
cleanup() {
    local status=$?
    if $installed_by_us; then
        step "removing the package (dpkg -r driftlab)"
        dpkg -r driftlab >"$work/dpkg-r.log" 2>&1 || {
            cat "$work/dpkg-r.log" >&2
            status=1
        }
    fi
    rm -rf "$work"
    exit "$status"
}
trap cleanup EXIT

step "cpack -G DEB into $work/out"
cpack -G DEB -B "$work/out" --config "$build/CPackConfig.cmake" >"$work/cpack.log" 2>&1 ||
    { cat "$work/cpack.log" >&2; fail "cpack failed"; }
debs=("$work"/out/driftlab_*.deb)
if ((${#debs[@]} != 1)) || [[ ! -f ${debs[0]} ]]; then
    fail "expected one driftlab_*.deb, found: ${debs[*]}"
fi
deb=${debs[0]}
step "built $(basename "$deb") ($(stat -c %s "$deb") bytes)"

step "control fields (dpkg-deb -I)"
field() { dpkg-deb -f "$deb" "$1"; }
[[ $(field Package) == driftlab ]] || fail "Package is '$(field Package)'"
[[ $(field Version) == "$version-1" ]] || fail "Version is '$(field Version)', expected $version-1"
[[ $(field Section) == science ]] || fail "Section is '$(field Section)'"
[[ -n $(field Maintainer) ]] || fail "no Maintainer"
[[ $(field Description) == *"feed axes"* ]] || fail "Description: $(field Description)"
depends=$(field Depends)
step "Depends: $depends"
# One package name a line, versions and alternatives dropped.
tr ',|' '\n' <<<"$depends" | sed 's/^ *//; s/[ (].*//' >"$work/depends.txt"
# From dpkg-shlibdeps: the Qt libraries the executables link, and others.
for package in libqt6core6 libqt6gui6 libqt6widgets6 libqt6sql6 libmodbus5 libqcustomplot2.1-qt6; do
    grep -qxF "$package" "$work/depends.txt" ||
        fail "Depends lacks $package (dpkg-shlibdeps did not run?)"
done
# What shlibdeps cannot see: the SQLite driver plugin the store loads by name.
grep -qxF libqt6sql6-sqlite "$work/depends.txt" || fail "Depends lacks libqt6sql6-sqlite"
[[ $(field Recommends) == *libqt6sql6-psql* ]] || fail "Recommends lacks libqt6sql6-psql"
dpkg-deb -I "$deb" >/dev/null

step "contents (dpkg-deb -c)"
dpkg-deb -c "$deb" | awk '{print $6}' | sed 's#^\./#/#' >"$work/contents.txt"
for path in /usr/bin/driftlab /usr/bin/driftlab-cli \
    /usr/share/applications/$app_id.desktop \
    /usr/share/metainfo/$app_id.metainfo.xml \
    /usr/share/icons/hicolor/scalable/apps/$app_id.svg \
    /usr/share/icons/hicolor/48x48/apps/$app_id.png \
    /usr/share/icons/hicolor/256x256/apps/$app_id.png \
    /usr/share/driftlab/procedures/iso230-2-x-axis.json \
    /usr/share/driftlab/devices/temperature-8ch-pt100.json \
    /usr/share/driftlab/examples/x-axis-moving-state/campaign.json \
    /usr/share/driftlab/linuxcnc/driftlab_eoffset.hal \
    /usr/share/driftlab/linuxcnc/driftlab_eoffset.py \
    /usr/share/doc/driftlab/README.md \
    /usr/share/doc/driftlab/docs/packaging.md \
    /usr/share/man/man1/driftlab.1.gz /usr/share/man/man1/driftlab-cli.1.gz; do
    grep -qxF "$path" "$work/contents.txt" || fail "the package lacks $path"
done
# Nothing outside /usr, nothing under /usr/local (a prefix left at CMake's default).
outside=$(grep -v -e '^/$' -e '^/usr/' "$work/contents.txt" || true)
[[ -z $outside ]] || fail "files outside /usr: $outside"
! grep -q '^/usr/local' "$work/contents.txt" || fail "files under /usr/local"

step "unpacked: desktop entry, AppStream metadata, icons, executables"
root=$work/root
dpkg-deb -x "$deb" "$root"
desktop-file-validate "$root/usr/share/applications/$app_id.desktop" ||
    fail "desktop-file-validate"
icon=$(sed -n 's/^Icon=//p' "$root/usr/share/applications/$app_id.desktop")
[[ $icon == "$app_id" ]] || fail "the desktop entry's Icon is '$icon'"
# --no-net: the metadata must be valid offline (CI has no network).
appstreamcli validate --no-net "$root/usr/share/metainfo/$app_id.metainfo.xml" ||
    fail "appstreamcli validate"
newest=$(sed -n 's/.*<release version="\([^"]*\)".*/\1/p' \
    "$root/usr/share/metainfo/$app_id.metainfo.xml" | head -n 1)
[[ $newest == "$version" ]] ||
    fail "the metainfo's newest release is '$newest', the project is $version (add a <release>)"
for size in 16 24 32 48 64 128 256; do
    png=$root/usr/share/icons/hicolor/${size}x$size/apps/$app_id.png
    file "$png" | grep -q "PNG image data, $size x $size," || fail "$png: $(file -b "$png")"
done
[[ -x $root/usr/share/driftlab/linuxcnc/driftlab_eoffset.py ]] ||
    fail "the LinuxCNC component is not executable"
# The man pages come from each executable's --help: they list its options.
zcat "$root/usr/share/man/man1/driftlab-cli.1.gz" | grep -q '^simulate ' ||
    fail "driftlab-cli.1 lacks the commands"
zcat "$root/usr/share/man/man1/driftlab.1.gz" | grep -q 'screenshots' ||
    fail "driftlab.1 lacks the options"
file "$root/usr/bin/driftlab-cli" | grep -q ', stripped' || fail "driftlab-cli is not stripped"
[[ $("$root/usr/bin/driftlab-cli" --version) == "driftlab-cli $version" ]] ||
    fail "the unpacked driftlab-cli --version says '$("$root/usr/bin/driftlab-cli" --version)'"

if ((EUID != 0)); then
    echo "SKIPPED: installing the package (dpkg -i) needs root; the checks above passed"
    exit $skipped
fi

if dpkg-query -W -f='${Status}' driftlab 2>/dev/null | grep -q 'ok installed'; then
    step "removing a driftlab installed before this test"
    dpkg -r driftlab >/dev/null
fi
step "dpkg -i $(basename "$deb")"
installed_by_us=true
dpkg -i "$deb" >"$work/dpkg-i.log" 2>&1 || { cat "$work/dpkg-i.log" >&2; fail "dpkg -i"; }
[[ $(dpkg-query -W -f='${Version}' driftlab) == "$version-1" ]] || fail "dpkg-query"

cli=/usr/bin/driftlab-cli
export HOME=$work/home XDG_RUNTIME_DIR=$work/home XDG_CONFIG_HOME=$work/home/.config
mkdir -m 0700 "$HOME"
cd "$work"
step "installed driftlab-cli: --version, simulate, info, import, info from the store"
[[ $($cli --version) == "driftlab-cli $version" ]] || fail "driftlab-cli --version: $($cli --version)"
$cli simulate --out "$work/campaign" --runs S1 --seed 1 >/dev/null 2>"$work/simulate.err" ||
    { cat "$work/simulate.err" >&2; fail "simulate"; }
$cli info "$work/campaign" --json >"$work/info.json"
python3 - "$work/info.json" <<'EOF' || fail "info --json of the simulated bundle"
import json, sys
info = json.load(open(sys.argv[1]))
runs = info["runs"]
assert [r["id"] for r in runs] == ["S1"], runs
assert runs[0]["samples"] > 0 and runs[0]["positioning"] > 0, runs[0]
assert any(c["role"] == "nut" for c in info["channels"]), info["channels"]
EOF
# The store goes through Qt's QSQLITE plugin: the Depends shlibdeps cannot see.
id=$($cli import "$work/campaign" --db "$work/lab.sqlite" 2>"$work/import.err") ||
    { cat "$work/import.err" >&2; fail "import into SQLite"; }
$cli info --db "$work/lab.sqlite" --campaign "$id" --json >"$work/stored.json"
python3 -c 'import json,sys; a,b=(json.load(open(p)) for p in sys.argv[1:]); assert a["runs"]==b["runs"], (a["runs"], b["runs"])' \
    "$work/info.json" "$work/stored.json" || fail "the stored campaign differs from the bundle"
step "simulated S1, imported as campaign $id, same runs and counts from the store"

step "installed driftlab-cli: a shipped procedure run on the simulated rig"
logged=$($cli run --procedure /usr/share/driftlab/procedures/iso230-2-x-axis.json --rig sim \
    --db "$work/lab.sqlite" 2>"$work/run.err") || { tail -n 5 "$work/run.err" >&2; fail "run"; }
$cli iso230-2 --db "$work/lab.sqlite" --campaign "$logged" --json >"$work/iso.json"
python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); assert r["A"] > 0, r' "$work/iso.json" ||
    fail "iso230-2 of the logged run"
step "logged campaign $logged, ISO 230-2 evaluated"

step "installed driftlab: --version, --help, a start under Xvfb that saves its pages"
gui=/usr/bin/driftlab
[[ $(QT_QPA_PLATFORM=offscreen $gui --version) == *"$version"* ]] || fail "driftlab --version"
QT_QPA_PLATFORM=offscreen $gui --help | grep -q -- '--screenshots' || fail "driftlab --help"
# The xcb platform plugin, as on a lab desktop (not offscreen).
timeout 180 xvfb-run -a -s "-screen 0 1280x800x24" $gui --screenshots "$work/shots" \
    >"$work/gui.log" 2>&1 || { tail -n 20 "$work/gui.log" >&2; fail "driftlab under Xvfb"; }
shots=("$work"/shots/gui-*.png)
((${#shots[@]} >= 6)) || fail "driftlab saved ${#shots[@]} pages: ${shots[*]}"
step "driftlab saved ${#shots[@]} pages under Xvfb"

step "dpkg -r driftlab"
installed_by_us=false
dpkg -r driftlab >/dev/null
[[ ! -e $cli && ! -e $gui ]] || fail "dpkg -r left the executables"
step "installed, used and removed $(basename "$deb")"
