"""A headless simulated one-axis LinuxCNC 2.9 machine for DriftLab's tests.

LinuxCNC runs as `linuxcnc -r INI` (-r: output to our stdout, not to
~/linuxcnc_*.txt); its [DISPLAY]DISPLAY is the test's own script, and LinuxCNC
shuts down when that script exits and returns its exit code. One instance per
host (LinuxCNC keeps /tmp/linuxcnc.lock and one HAL), so ctest runs these
tests RUN_SERIAL.
"""

import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

SKIP = 77  # ctest SKIP_RETURN_CODE: LinuxCNC is not installed here
HERE = os.path.dirname(os.path.abspath(__file__))
SYSTEM_NML = "/usr/share/linuxcnc/linuxcnc.nml"
# rtapi_app refuses to run as root unless it may drop to another user; CI and
# the reference machine run as root, so it drops to `nobody`.
FALLBACK_UID = 65534

HAL = """\
loadrt [KINS]KINEMATICS
loadrt [EMCMOT]EMCMOT servo_period_nsec=[EMCMOT]SERVO_PERIOD num_joints=[KINS]JOINTS
addf motion-command-handler servo-thread
addf motion-controller servo-thread
# A perfect drive: the motor is where it is told to be.
net x-motor joint.0.motor-pos-cmd => joint.0.motor-pos-fb
net estop-loop iocontrol.0.user-enable-out => iocontrol.0.emc-enable-in
"""

INI = """\
[EMC]
VERSION = 1.1
MACHINE = driftlab-sim-x
NML_FILE = {nml}
[DISPLAY]
DISPLAY = {display}
[TASK]
TASK = milltask
CYCLE_TIME = 0.001
[RS274NGC]
PARAMETER_FILE = sim.var
[EMCIO]
EMCIO = io
CYCLE_TIME = 0.100
TOOL_TABLE = sim.tbl
[EMCMOT]
EMCMOT = motmod
SERVO_PERIOD = 1000000
[HAL]
HALFILE = sim.hal
{halfiles}
[TRAJ]
COORDINATES = X
LINEAR_UNITS = mm
ANGULAR_UNITS = degree
MAX_LINEAR_VELOCITY = 2000
[KINS]
JOINTS = 1
KINEMATICS = trivkins coordinates=X
[AXIS_X]
MIN_LIMIT = -10
MAX_LIMIT = 710
MAX_VELOCITY = 2000
MAX_ACCELERATION = 20000
{axis_extra}
[JOINT_0]
TYPE = LINEAR
MIN_LIMIT = -10
MAX_LIMIT = 710
MAX_VELOCITY = 2000
MAX_ACCELERATION = 20000
FERROR = 1
MIN_FERROR = 1
# Home where it stands: no switches on a simulated axis.
HOME = 0
HOME_OFFSET = 0
HOME_SEARCH_VEL = 0
HOME_LATCH_VEL = 0
HOME_SEQUENCE = 0
{joint_extra}
{extra_sections}
"""


def available():
    """LinuxCNC and its Python modules under Debian's python3."""
    if not (shutil.which("linuxcnc") and shutil.which("halrun") and os.path.exists(SYSTEM_NML)):
        return False
    probe = subprocess.run(["/usr/bin/python3", "-c", "import linuxcnc, hal"],
                           capture_output=True)
    return probe.returncode == 0


def quiet_unless_failed(main):
    """Runs main() with its prints kept back: a passing acceptance test prints
    nothing; a failure (or a skip) prints every table and step it checked."""
    import contextlib
    import io
    kept = io.StringIO()
    try:
        with contextlib.redirect_stdout(kept):
            code = main()
    except SystemExit as e:  # skip_unless_available() and the like
        code = e.code
    if code:
        sys.stdout.write(kept.getvalue())
    return code


def skip_unless_available():
    if not available():
        print("SKIP: LinuxCNC (Debian linuxcnc-uspace) is not installed")
        sys.exit(SKIP)


def local_nml():
    """linuxcnc.nml without its remote side: no TCP=5005 server on the
    buffers (parallel hosts, or a second test on this host, would fight for
    the port) and no xemc remote-client entries. linuxcncsvr then says
    "Cannot run with remote port equal to NULL" and serves shared memory only."""
    lines = []
    with open(SYSTEM_NML) as nml:
        for line in nml:
            fields = line.split()
            if fields[:2] == ["P", "xemc"]:
                continue
            lines.append(line.replace(" TCP=5005", ""))
    text = "".join(lines)
    if "TCP=" in text:
        raise RuntimeError(SYSTEM_NML + ": a TCP port is left in the NML file")
    return text


def rtapi_env(workdir):
    env = dict(os.environ)
    if os.geteuid() == 0:
        # rtapi_app, now `nobody`, binds its socket in a folder it owns; the
        # work folder (0700 from mkdtemp) must let it pass through (0711).
        fifo_dir = os.path.join(workdir, "rtapi")
        os.makedirs(fifo_dir, exist_ok=True)
        os.chown(fifo_dir, FALLBACK_UID, -1)
        os.chmod(workdir, 0o711)
        env["RTAPI_UID"] = str(FALLBACK_UID)
        env["RTAPI_FIFO_PATH"] = os.path.join(fifo_dir, "fifo")
    # The display scripts are /usr/bin/python3 programs; a pyenv python on
    # PATH must not shadow the system one inside LinuxCNC's scripts.
    env["PATH"] = "/usr/bin:/bin:" + env.get("PATH", "")
    return env


def cleanup(env):
    """What LinuxCNC leaves behind when a run is killed: HAL, rtapi_app."""
    subprocess.run(["halrun", "-U"], env=env, capture_output=True, timeout=30)


def run(display, plan, halfiles=(), axis_extra="", joint_extra="", extra_sections="",
        timeout_s=60):
    """Starts the simulated machine with `display` (a script in this folder)
    as its display, `plan` (JSON) beside the INI for the display to read.
    Returns (exit code, the run's output, the display's result JSON, seconds)."""
    workdir = tempfile.mkdtemp(prefix="driftlab-lcnc-")
    try:
        return _run_in(workdir, display, plan, halfiles, axis_extra, joint_extra,
                       extra_sections, timeout_s)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)


def _run_in(workdir, display, plan, halfiles, axis_extra, joint_extra, extra_sections,
            timeout_s):
    with open(os.path.join(workdir, "driftlab.nml"), "w") as f:
        f.write(local_nml())
    with open(os.path.join(workdir, "sim.hal"), "w") as f:
        f.write(HAL)
    for name in ("sim.var", "sim.tbl"):
        open(os.path.join(workdir, name), "w").close()
    result_path = os.path.join(workdir, "result.json")
    plan = dict(plan, result=result_path)
    with open(os.path.join(workdir, "plan.json"), "w") as f:
        json.dump(plan, f)
    ini = os.path.join(workdir, "sim.ini")
    with open(ini, "w") as f:
        f.write(INI.format(nml=os.path.join(workdir, "driftlab.nml"),
                           display=os.path.join(HERE, display),
                           halfiles="\n".join("HALFILE = " + h for h in halfiles),
                           axis_extra=axis_extra, joint_extra=joint_extra,
                           extra_sections=extra_sections))
    env = rtapi_env(workdir)
    started = time.monotonic()
    process = subprocess.Popen(["linuxcnc", "-r", ini], cwd=workdir, env=env,
                               stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True,
                               start_new_session=True)
    timed_out = False
    try:
        output, _ = process.communicate(timeout=timeout_s)
    except subprocess.TimeoutExpired:
        timed_out = True
        # The display hung: stop the whole session, then clear HAL.
        os.killpg(process.pid, signal.SIGTERM)
        try:
            output, _ = process.communicate(timeout=5)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            output, _ = process.communicate()
        output += "\nTIMEOUT: LinuxCNC did not finish in %d s\n" % timeout_s
    seconds = time.monotonic() - started
    # LinuxCNC's script exits 0 after its own cleanup on SIGTERM: a timeout is
    # a failure all the same.
    code = 124 if timed_out else process.returncode
    if code != 0:
        cleanup(env)
    result = None
    if os.path.exists(result_path):
        with open(result_path) as f:
            result = json.load(f)
    return code, output, result, seconds
