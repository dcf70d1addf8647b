"""A sweep spec (YAML) checked as a whole and expanded into its runs, before anything starts
(twin_tools.sweep.cli). Format (config/sweeps/ambient_study.yaml is an example):

  scenarios: [baseline_urban, hybrid_urban]   # launch/<name>.launch; the scenario sets the architecture
  jobs: 2                   # runs at a time on this machine (CLI --jobs wins); Slurm: the array's throttle
  out: results/sweeps/NAME  # results folder, relative to the repository (CLI --out wins)
  fixed:                    # launch arguments of every run (twin_tools.launch.args): name: value
    until: 300
  vary:                     # launch arguments, each a list of values: one axis of the matrix
    ambient: [0, 25, 40]
    engine: [map]
  config:                   # keys of the YAML configs, set in a copy of the config folder per run
    battery.yaml:           #   file (relative to the config folder) -> key path ('/') -> values
      pack/cells_in_parallel: [5, 7, 9]
  slurm:                    # --slurm only: sbatch options, each written as `#SBATCH --name=value`
    time: "01:00:00"

The runs are the product scenarios x every axis (in this order). Every name, value, file and key
is checked here: an unknown scenario, launch argument, config file or key (never added: the key
must exist in that file), a value of the wrong type or out of range stops the sweep with a
message naming the spec file and the key. Paths in the spec are relative to the repository.
"""
import itertools
import os
import re

import yaml

from twin_tools.launch import args as launch_args
from twin_tools.sweep import config_edit as sweep_yaml

TOP_KEYS = ("scenarios", "jobs", "out", "fixed", "vary", "config", "slurm")
SLURM_KEYS = ("partition", "time", "cpus-per-task", "mem", "account", "qos", "constraint", "nodes")
# launch arguments a sweep sets itself
RESERVED_ARGS = {"out": "each run's folder is OUT/runs/<run-id>", "rviz": "no rviz in a sweep"}
# config keys the launch or a node overwrites: setting them in a copy would change nothing
SHADOWED = {
    ("vehicle.yaml", "chassis/payload_kg"): "the launch argument payload sets it (sweep payload instead)",
    ("mission.yaml", "cycle_file"): "the launch arguments cycle / cycle_file set it",
    ("mission.yaml", "vehicle"): "the vehicle node sets the mission's vehicle from vehicle.yaml",
    ("mission.yaml", "profile_csv_file"): "the vehicle node writes the profile into the run's folder",
}


class SpecError(Exception):
    """Every problem of a spec, one line each ('SPEC: key: message')."""


def arg_text(v):
    """A spec value (YAML scalar) as the text of a name:=value launch argument."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return repr(v)
    return str(v)


def short_name(axis):
    """Axis name in a run id: the argument, or the last part of a config key."""
    return axis.split("/")[-1].split(":")[-1]


def slug(v):
    return re.sub(r"[^A-Za-z0-9.+-]+", "-", arg_text(v)).strip("-") or "x"


class Spec:
    """The checked spec: .scenarios, .fixed {arg: text}, .axes [(name, kind, values, extra)],
    .jobs, .out, .slurm {option: text}, .path."""

    def __init__(self, path, repo, cli_args=(), jobs=None, out=None):
        self.path, self.repo = os.path.abspath(path), repo
        self.errors = []
        try:
            with open(path) as f:
                d = yaml.safe_load(f)
        except OSError as e:
            raise SpecError("%s: cannot read: %s" % (path, e.strerror))
        except yaml.YAMLError as e:
            raise SpecError("%s: not valid YAML: %s" % (path, str(e).replace("\n", " ")))
        if not isinstance(d, dict):
            raise SpecError("%s: expected a mapping with the keys %s" % (path, ", ".join(TOP_KEYS)))
        for k in d:
            if k not in TOP_KEYS:
                self.err(k, "unknown key (known: %s)" % ", ".join(TOP_KEYS))
        self.scenarios = self._scenarios(d.get("scenarios"))
        self.jobs = self._jobs(d.get("jobs", 2) if jobs is None else jobs, "jobs" if jobs is None else "--jobs")
        self.out = out if out is not None else (os.path.join(repo, d["out"]) if isinstance(d.get("out"), str) else None)
        if "out" in d and not isinstance(d["out"], str):
            self.err("out", "expected a folder name, got %r" % (d["out"],))
        self.fixed = self._mapping(d, "fixed")
        self.vary = self._mapping(d, "vary")
        self.config = self._mapping(d, "config")
        for key in ("vary", "config"):  # present but empty: an axis forgotten, not a one-run sweep
            if key in d and not d[key]:
                self.err(key, "empty: give at least one axis (%s) or leave the key out"
                         % ("vary/<argument>: [values]" if key == "vary" else "config/<file>.yaml: {key: [values]}"))
        self.slurm = self._slurm(self._mapping(d, "slurm"))
        self.cli = set()
        for a in cli_args:  # name:=value on the command line: fixed arguments, override the spec
            name, sep, value = a.partition(":=")
            if not sep or not name:
                self.err("command line %s" % a, "expected name:=value")
            elif name in self.vary:
                self.err("command line %s" % a, "%s is an axis (vary/%s)" % (name, name))
            else:
                self.fixed[name] = value
                self.cli.add(name)
        self.fixed = self._fixed_args(self.fixed)
        self.axes = self._arg_axes(self.vary) + self._config_axes(self.config)
        if self.errors:
            raise SpecError("\n".join(self.errors))

    def err(self, key, msg):
        self.errors.append("%s: %s: %s" % (self.path, key, msg))

    def _scenarios(self, s):
        if s is None:
            self.err("scenarios", "missing (a list of scenarios, e.g. [baseline_urban, hybrid_urban])")
            return []
        if isinstance(s, str):
            s = [s]
        if not isinstance(s, list) or not s:
            self.err("scenarios", "expected a non-empty list of scenario names")
            return []
        known = sorted(f[:-7] for f in os.listdir(os.path.join(self.repo, "launch")) if f.endswith(".launch"))
        for x in s:
            if x not in known:
                self.err("scenarios", "unknown scenario '%s' (known: %s)" % (x, ", ".join(known)))
        if len(set(map(str, s))) != len(s):
            self.err("scenarios", "a scenario is listed twice")
        return [str(x) for x in s]

    def _jobs(self, j, key):
        if isinstance(j, bool) or not isinstance(j, int) or j < 1:
            self.errors.append("%s: %s: expected a whole number >= 1, got %r" % (self.path, key, j))
            return 1
        return j

    def _mapping(self, d, key):
        v = d.get(key)
        if v is None:
            return {}
        if not isinstance(v, dict):
            self.err(key, "expected a mapping (name: value), got %r" % (v,))
            return {}
        return dict(v)

    def _slurm(self, s):
        out = {}
        for k, v in s.items():
            if k not in SLURM_KEYS:
                self.err("slurm/%s" % k, "unknown sbatch option (known: %s)" % ", ".join(SLURM_KEYS))
            elif isinstance(v, (dict, list)) or v is None or not re.fullmatch(r"[\w:.,=+-]+", arg_text(v)):
                self.err("slurm/%s" % k, "expected one plain value, got %r" % (v,))
            else:
                out[k] = arg_text(v)
        return out

    def _check_arg(self, key, name, value, config=None):
        """The normalised launch-argument text, or None (error recorded)."""
        if name in RESERVED_ARGS:
            self.err(key, "launch argument '%s' cannot be set in a sweep (%s)" % (name, RESERVED_ARGS[name]))
            return None
        if name not in launch_args.ARGS:
            self.err(key, "unknown launch argument '%s' (known: %s)" % (
                name, ", ".join(sorted(n for n in launch_args.ARGS if n not in RESERVED_ARGS))))
            return None
        if isinstance(value, (dict, list)) or value is None:
            self.err(key, "expected one value, got %r" % (value,))
            return None
        text = arg_text(value)
        if name == "config" or name == "cycle_file":  # paths relative to the repository
            text = os.path.join(self.repo, text)
        try:
            return launch_args.ARGS[name](text, self.repo, config)
        except ValueError as e:
            self.err(key, str(e))
            return None

    def base_configs(self):
        """The config folders the runs start from (the fixed or varied `config` argument)."""
        if "config" in self.vary and isinstance(self.vary["config"], list):
            return [os.path.join(self.repo, arg_text(c)) for c in self.vary["config"]]
        if "config" in self.fixed:
            return [self.fixed["config"]]
        return [os.path.join(self.repo, "config")]

    def _fixed_args(self, fixed):
        out = {}
        config = os.path.join(self.repo, arg_text(fixed["config"])) if "config" in fixed else None
        for name in ["config"] * ("config" in fixed) + [n for n in fixed if n != "config"]:
            key = ("command line %s:=%s" % (name, fixed[name])) if name in self.cli else "fixed/%s" % name
            if name in self.vary:
                self.err(key, "also an axis (vary/%s): give it in one place" % name)
                continue
            t = self._check_arg(key, name, fixed[name], config)
            if t is not None:
                out[name] = t
        return out

    def _values(self, key, v):
        if not isinstance(v, list) or not v:
            self.err(key, "expected a non-empty list of values (one axis of the matrix), got %r" % (v,))
            return None
        if len({repr(x) for x in v}) != len(v):
            self.err(key, "a value is listed twice: %r" % (v,))
            return None
        return v

    def _arg_axes(self, vary):
        axes = []
        configs = self.base_configs()
        for name, v in vary.items():
            vals = self._values("vary/%s" % name, v)
            if vals is None:
                continue
            texts = []
            for x in vals:
                t = None
                for c in (configs if name != "config" else [None]):
                    t = self._check_arg("vary/%s" % name, name, x, c)
                texts.append(t)
            axes.append((str(name), "arg", vals, texts))
        return axes

    def _config_axes(self, config):
        axes = []
        for fname, keys in config.items():
            fname = str(fname)
            if not isinstance(keys, dict) or not keys:
                self.err("config/%s" % fname, "expected a mapping key/path: [values, ...]")
                continue
            if not fname.endswith(".yaml") or fname.startswith(("data/", "sweeps/", "/")) or ".." in fname.split("/"):
                self.err("config/%s" % fname, "expected a YAML file of the config folder (e.g. battery.yaml, aux/fan_only.yaml)")
                continue
            texts = {}
            for base in self.base_configs():
                p = os.path.join(base, fname)
                if not os.path.isfile(p):
                    avail = sorted(f for f in os.listdir(base) if f.endswith(".yaml")) if os.path.isdir(base) else []
                    self.err("config/%s" % fname, "no such file %s (files: %s)" % (p, ", ".join(avail)))
                    texts = None
                    break
                with open(p) as f:
                    texts[base] = f.read()
            if texts is None:
                continue
            for key, v in keys.items():
                key = str(key)
                where = "config/%s:%s" % (fname, key)
                for (sf, sk), why in SHADOWED.items():
                    if sf == fname and (key == sk or key.startswith(sk + "/")):
                        self.err(where, "not sweepable: %s" % why)
                        break
                else:
                    vals = self._values(where, v)
                    if vals is None:
                        continue
                    written, ok = [], True
                    for x in vals:
                        for base, text in texts.items():
                            try:
                                _, _, w = sweep_yaml.set_key(text, key, x)
                            except sweep_yaml.KeyPathError as e:
                                self.err(where, "%s (file %s)" % (e, os.path.join(base, fname)))
                                ok = False
                                break
                        if not ok:
                            break
                        written.append(w)
                    if ok:
                        axes.append(("%s:%s" % (fname, key), "config", vals, (fname, key)))
        return axes

    def runs(self, out):
        """[{id, index, scenario, values {axis: value}, args [name:=value], edits [(file, key, value)],
        dir}] in matrix order: scenarios x axes (the last axis varies fastest)."""
        runs = []
        multi = {a[0] for a in self.axes if len(a[2]) > 1}
        combos = itertools.product(self.scenarios, *[list(range(len(a[2]))) for a in self.axes])
        for i, combo in enumerate(combos):
            scenario, picks = combo[0], combo[1:]
            args = dict(self.fixed)
            values, edits = {}, []
            rid = "%03d_%s" % (i, scenario)
            for (name, kind, vals, extra), k in zip(self.axes, picks):
                values[name] = vals[k]
                if kind == "arg":
                    args[name] = extra[k]
                else:
                    edits.append((extra[0], extra[1], vals[k]))
                if name in multi:
                    rid += "_%s%s" % (short_name(name), slug(vals[k]))
            d = os.path.join(out, "runs", rid)
            if edits:  # a copy of the config folder, with the keys set, in the run's folder
                args["config"] = os.path.join(d, "config")
            order = ["config"] if "config" in args else []
            runs.append({"id": rid, "index": i, "scenario": scenario, "values": values,
                         "base_config": self.fixed.get("config") or (
                             os.path.join(self.repo, arg_text(values["config"])) if "config" in values
                             else os.path.join(self.repo, "config")),
                         "args": ["%s:=%s" % (n, args[n]) for n in order + sorted(n for n in args if n != "config")],
                         "edits": edits, "dir": d})
        return runs
