"""The config of "everything at the 10 ms base step" (`twin bench rates`, test ros_rates_scenario):
a copy of the config folder with the cooling and aftertreatment macro steps at 0.01 s."""
import os
import shutil

from twin_tools.paths import REPO


def all_fast_config(tmp):
    cfg = os.path.join(tmp, "config")
    shutil.copytree(os.path.join(REPO, "config"), cfg, ignore=shutil.ignore_patterns("data"))
    os.symlink(os.path.join(REPO, "config", "data"), os.path.join(cfg, "data"))
    for name, old, new in (("cooling.yaml", "macro_step_s: 0.1", "macro_step_s: 0.01"),
                           ("aftertreatment.yaml", "macro_step_s: 0.1", "macro_step_s: 0.01")):
        p = os.path.join(cfg, name)
        with open(p) as f:
            t = f.read()
        assert old in t, (name, old)
        with open(p, "w") as f:
            f.write(t.replace(old, new, 1))
    return cfg
