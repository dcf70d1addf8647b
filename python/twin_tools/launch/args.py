"""Checks the name:=value arguments of `twin run` before anything starts, and writes them back
normalised (numbers in plain decimal notation, which roslaunch's substitution args always read
as numbers: `step:=1e-3` becomes `step:=0.001`).

Usage: python3 -m twin_tools.launch.args REPO SCENARIO name:=value ...   -> one normalised name:=value per line
Exit 1 with a message naming the argument when one is unknown, mistyped or out of range.
"""
import math
import os
import sys
from decimal import Decimal

from twin_tools import wiring


def number(lo, hi, integer=False):
    def check(v, repo, config=None):
        try:
            x = float(v)
        except ValueError:
            raise ValueError("'%s' is not a number" % v)
        if not math.isfinite(x):
            raise ValueError("'%s' is not finite" % v)
        if not lo <= x <= hi:
            raise ValueError("%s is outside [%g, %g]" % (v, lo, hi))
        if integer and x != int(x):
            raise ValueError("%s is not an integer" % v)
        return repr(int(x)) if integer else format(Decimal(repr(x)), "f")
    return check


def choice(*options):
    def check(v, repo, config=None):
        if v not in options:
            raise ValueError("'%s' is not one of %s" % (v, ", ".join(options)))
        return v
    return check


def existing(kind, folder=None, suffix=""):
    def check(v, repo, config=None):
        folder_ = folder.format(config=config or os.path.join(repo, "config")) if folder else None
        path = os.path.join(repo, folder_, v + suffix) if folder_ else v
        ok = os.path.isdir(path) if kind == "dir" else os.path.isfile(path)
        if not ok:
            avail = ""
            if folder_ and os.path.isdir(os.path.join(repo, folder_)):
                avail = "; available: " + ", ".join(sorted(
                    f[: -len(suffix)] if suffix else f for f in os.listdir(os.path.join(repo, folder_))
                    if f.endswith(suffix)))
            raise ValueError("'%s' not found (%s)%s" % (v, path, avail))
        return os.path.abspath(path) if not folder else v
    return check


ARGS = {
    "ambient": number(-40.0, 55.0),          # [degC]: the studies use 0, 25, 40
    "pressure": number(50.0, 120.0),         # [kPa] ambient pressure (101.325 at sea level; ~80 at 2000 m)
    "start": choice("cold", "warm"),         # thermal start state (warm: the configs' warm_start/)
    "engine": choice("map", "1d"),
    "solver": choice("fsm", "tvd"),
    "mode": choice("nodes", "nodelets"),
    "step": number(1e-4, 1.0),               # [s]
    "until": number(0.0, 1e6),               # [s], 0 = whole mission
    "payload": number(0.0, 15000.0),         # [kg]
    "timeout": number(0.01, 600.0),          # [s wall]
    "window_steps": number(1, 100000, integer=True),  # [base steps] report window of the lock-step
    "record_period": number(0.0, 3600.0),    # [s]
    "rviz": choice("true", "false"),
    "aux": existing("file", "{config}/aux", ".yaml"),
    "gearbox": existing("file", "{config}/gearbox", ".yaml"),  # gear loss set
    "pack": existing("file", "{config}/battery_pack", ".yaml"),  # 48 V pack set (empty: battery.yaml's)
    "cycle": existing("file", "config/data/cycles/vecto", ".vdri"),
    "cycle_file": existing("file"),
    "config": existing("dir"),
    "architecture": choice("conventional", "p1_48v"),
    "thermal": choice("true", "false"),
    "thermal_thread": lambda v, repo, config=None: thread_name(v),  # nodelets: the thermal nodes' thread
    "hvac": choice("on", "off"),            # the hvac participant (cabin, heater, A/C); off: cooling's heater/
    "order": lambda v, repo, config=None: v,  # Gauss-Seidel groups: checked by the stepper before step 0
    "remote": lambda v, repo, config=None: remote_list(v),  # participants on another host
    "remote_host": lambda v, repo, config=None: host(v),
    "remote_user": lambda v, repo, config=None: word(v, "a user name"),
    "remote_ssh_port": number(1, 65535, integer=True),
    "remote_env_loader": lambda v, repo, config=None: absolute(v),
}

# the participants that may run on another host (the stepper and the recorder stay with the
# master and the results folder); which exist depends on the architecture and `thermal`
PARTICIPANTS = wiring.participants()  # launch/include/urban.launch: one include each


def fmu_file(v, repo, config=None):
    """An FMU for <participant>_fmu: an existing regular file named .fmu (its content is checked
    by the participant before step 0, naming the file and the problem)."""
    path = existing("file")(v, repo, config)
    if not path.endswith(".fmu"):
        raise ValueError("'%s' is not an .fmu file" % v)
    return path


def fmu_map_file(v, repo, config=None):
    """A mapping file for <participant>_fmu_map: an existing YAML mapping of keys (its keys are
    checked by the participant, naming the file and the key)."""
    import yaml
    path = existing("file")(v, repo, config)
    try:
        with open(path, "rb") as f:
            doc = yaml.safe_load(f.read().decode("utf-8"))
    except (OSError, UnicodeDecodeError, yaml.YAMLError) as e:
        raise ValueError("%s: not a readable YAML file: %s" % (path, str(e).replace("\n", " ")))
    if not isinstance(doc, dict) or not doc:
        raise ValueError("%s: %s" % (path, "empty" if not doc else "not a mapping of keys"))
    return path


# <participant>_fmu:=PATH.fmu serves that participant by an FMU; <participant>_fmu_map:=MAP.yaml
for _p in PARTICIPANTS:
    ARGS[_p + "_fmu"] = fmu_file
    ARGS[_p + "_fmu_map"] = fmu_map_file
SCENARIO_ARCHITECTURE = {"baseline_urban": "conventional", "hybrid_urban": "p1_48v"}


def remote_list(v):
    names = [p.strip() for p in v.split(",") if p.strip()]
    for n in names:
        if n not in PARTICIPANTS:
            raise ValueError("'%s' is not a participant that can run remotely (%s)" % (n, ", ".join(PARTICIPANTS)))
    if len(set(names)) != len(names):
        raise ValueError("'%s' names a participant twice" % v)
    return ",".join(names)


def host(v):
    if not v or not all(c.isalnum() or c in ".-:" for c in v):
        raise ValueError("'%s' is not a host name or an IP address" % v)
    return v


def word(v, what):
    if not v or not all(c.isalnum() or c in "._-" for c in v):
        raise ValueError("'%s' is not %s" % (v, what))
    return v


def thread_name(v):
    """A nodelet thread name as cosim/thread takes it (LockstepQueue::validThreadName: letters,
    digits, _; at most 64 characters); empty = the scenario's default."""
    if len(v) > 64 or not all(c.isalnum() or c == "_" for c in v):
        raise ValueError("'%s' is not a thread name (letters, digits, _; at most 64 characters)" % v)
    return v


def absolute(v):
    if not os.path.isabs(v):
        raise ValueError("'%s' is not an absolute path (a path on the remote host)" % v)
    return v


def present_participants(scenario, given):
    """The participants that run in this scenario with these arguments."""
    arch = given.get("architecture", SCENARIO_ARCHITECTURE.get(scenario, "conventional"))
    present = {"vehicle", "engine"}
    if given.get("thermal", "true") == "true":
        present |= {"aftertreatment", "cooling"}
        if given.get("hvac", "on") == "on":
            present |= {"hvac"}
    if arch == "p1_48v":
        present |= {"ems", "emachine", "battery"}
    return present, arch


# Launch arguments that select what a native participant reads by name (strings under /scenario/)
# and that an FMU cannot receive: the FMU participant hands an FMU the numeric scenario values
# only (its Real parameters scenario.<name>, src/fmi/README.md); an FMI 2.0 String parameter is
# not passed. argument -> (its neutral value, the participants whose models read it): start
# (cosim::scenarioWarmStart: src/{vehicle,aftertreatment,hvac,battery,cooling}/node), pack
# (/scenario/battery_pack: src/battery/node). The twin's exported FMUs start cold and carry the
# pack of config/battery.yaml; a supplier's FMU has its own. With an FMU serving such a
# participant, any other value is refused here (it would be silently ignored).
FMU_UNREACHABLE = {
    "start": ("cold", ("vehicle", "aftertreatment", "hvac", "battery", "cooling")),
    "pack": ("", ("battery",)),
}


def check_fmu(scenario, given):
    """<participant>_fmu only for a participant of the scenario; _fmu_map only with its _fmu; no
    FMU_UNREACHABLE argument the FMU would not receive."""
    present, arch = present_participants(scenario, given)
    for p in PARTICIPANTS:
        if p + "_fmu_map" in given and p + "_fmu" not in given:
            sys.exit("twin: argument '%s_fmu_map' given without %s_fmu:=PATH.fmu" % (p, p))
        if p + "_fmu" in given and p not in present:
            sys.exit("twin: argument '%s_fmu': %s is not a participant of %s (architecture %s, thermal %s, hvac %s)"
                     % (p, p, scenario, arch, given.get("thermal", "true"), given.get("hvac", "on")))
    for arg, (neutral, readers) in sorted(FMU_UNREACHABLE.items()):
        value = given.get(arg, neutral)
        for p in readers:
            if value != neutral and p + "_fmu" in given:
                sys.exit("twin: argument '%s:=%s' cannot reach %s_fmu:=%s: an FMU receives the scenario's numeric "
                         "values only (its parameters scenario.<name>), not %s; the FMU runs as it was exported "
                         "(the twin's FMUs: start:=cold, the pack of config/battery.yaml). Drop %s:= or %s_fmu:="
                         % (arg, value, p, given[p + "_fmu"], arg, arg, p))


def check_remote(scenario, given):
    """Cross-checks of the remote arguments (each one alone is checked above)."""
    remote = [p for p in given.get("remote", "").split(",") if p]
    if not remote:
        extra = sorted(k for k in given if k.startswith("remote_"))
        if extra:
            sys.exit("twin: argument '%s' given without remote:=PARTICIPANTS" % extra[0])
        return
    if "remote_host" not in given:
        sys.exit("twin: argument 'remote': remote_host:=ADDRESS is required")
    present, arch = present_participants(scenario, given)
    for n in remote:
        if n not in present:
            sys.exit("twin: argument 'remote': %s is not a participant of %s (architecture %s, thermal %s, hvac %s)"
                     % (n, scenario, arch, given.get("thermal", "true"), given.get("hvac", "on")))


def check_architecture(scenario, given):
    """A scenario file is one bus: an architecture:= that contradicts it is refused (the summary,
    the sweep tables and the reports name the run by its scenario), one that repeats it is fine."""
    want = SCENARIO_ARCHITECTURE.get(scenario)
    got = given.get("architecture")
    if want is not None and got is not None and got != want:
        other = [s for s, a in SCENARIO_ARCHITECTURE.items() if a == got]
        sys.exit("twin: argument 'architecture': %s is the %s bus; architecture:=%s contradicts it%s"
                 % (scenario, want, got, " (run %s)" % other[0] if other else ""))


def check_yaml_files(folder):
    """Every YAML of the config folder (and its aux/, gearbox/ and battery_pack/ sets) parses and is not empty, before
    roslaunch reads them (its errors name no file; an empty file loads nothing, silently)."""
    import yaml
    for sub in ("", "aux", "gearbox", "battery_pack"):
        d = os.path.join(folder, sub)
        if not os.path.isdir(d):
            continue
        for name in sorted(os.listdir(d)):
            if not name.endswith(".yaml"):
                continue
            path = os.path.join(d, name)
            if not os.path.isfile(path):
                sys.exit("twin: config file %s: %s, not a YAML file" % (path, "a folder" if os.path.isdir(path) else "not a regular file"))
            try:
                with open(path, "rb") as f:
                    doc = yaml.safe_load(f.read().decode("utf-8"))
            except OSError as e:
                sys.exit("twin: config file %s: cannot be read: %s" % (path, e.strerror or e))
            except UnicodeDecodeError as e:
                sys.exit("twin: config file %s: not UTF-8 text (byte %d): %s" % (path, e.start, e.reason))
            except yaml.YAMLError as e:
                sys.exit("twin: config file %s: not valid YAML: %s" % (path, str(e).replace("\n", " ")))
            if not isinstance(doc, dict) or not doc:
                sys.exit("twin: config file %s: %s" % (path, "empty" if not doc else "not a mapping of keys"))


def main():
    repo, scenario, pairs = sys.argv[1], sys.argv[2], sys.argv[3:]
    out, seen, given = [], set(), {}
    config = None
    for p in pairs:  # the config folder first: the auxiliary and gear loss sets live in it
        if p.startswith("config:="):
            config = os.path.abspath(p[len("config:="):])
    for p in pairs:
        name, sep, value = p.partition(":=")
        if not sep or not name:
            sys.exit("twin: argument '%s': expected name:=value" % p)
        if name not in ARGS:
            sys.exit("twin: unknown argument '%s' for %s; known: %s" % (name, scenario, ", ".join(sorted(ARGS))))
        if name in seen:
            sys.exit("twin: argument '%s' given twice" % name)
        seen.add(name)
        try:
            given[name] = ARGS[name](value, repo, config)
            out.append("%s:=%s" % (name, given[name]))
        except ValueError as e:
            sys.exit("twin: argument '%s': %s" % (name, e))
    check_architecture(scenario, given)
    check_remote(scenario, given)
    check_fmu(scenario, given)
    check_yaml_files(config or os.path.join(repo, "config"))
    print("\n".join(out))


if __name__ == "__main__":
    main()
