"""The tables the benches measured, as Markdown files: docs/bench/<name>.md for a full benchmark
(committed beside the code it measured), results/bench/<name>.md for a partial one (--until, a
shorter --duration), so a quick check never replaces a full measurement in docs/. Each file states
the command, the date, the machine (CPUs, CPU model) and its load at the start and the end."""
import os
import shlex
import sys
import time

from twin_tools.paths import REPO

DOCS_DIR = os.path.join(REPO, "docs", "bench")
PARTIAL_DIR = os.path.join(REPO, "results", "bench")


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "CPU model unknown"


class Measurement:
    """Started with the bench: its command line, date and the machine's load at the start."""

    def __init__(self, argv):
        self.command = " ".join(["scripts/twin", "bench"] + [shlex.quote(x) for x in argv])
        self.date = time.strftime("%Y-%m-%d")
        self.load_start = os.getloadavg()[0]

    def header(self):
        return ("`%s`, measured %s on %d CPUs (%s); load average %.1f at the start, %.1f at the end."
                % (self.command, self.date, os.cpu_count() or 0, cpu_model(), self.load_start,
                   os.getloadavg()[0]))

    def write(self, name, title, body, partial):
        """Writes `# title`, the header line and the body lines; returns the path."""
        d = PARTIAL_DIR if partial else DOCS_DIR
        os.makedirs(d, exist_ok=True)
        path = os.path.join(d, name + ".md")
        with open(path, "w") as f:
            f.write("\n".join(["# " + title, "", self.header(), ""] + list(body)).rstrip("\n") + "\n")
        print("bench: table written to %s%s" % (os.path.relpath(path, REPO), " (a partial run: docs/bench/ keeps "
              "the full benchmark)" if partial else ""), file=sys.stderr)
        return path
