"""A two-node Slurm cluster on this machine for the sweep's --slurm test (test_sweep_slurm.py).

Each compute node is a network namespace and a UTS namespace of its own (its own hostname, its
own address on a veth pair to this host, /30 each), holding one slurmd with its own NodeName,
NodeHostname, address, spool, pid and log files. slurmctld and munged run on this host:
slurmctld listens on every address of this host, and each node reaches it at this host's address
on node 1's link through its default route (this host delivers to its own addresses; nothing is
forwarded). Both nodes see this machine's one file system (the repository, the sweep's folder,
munged's socket: a path socket crosses network namespaces), as a real cluster's nodes see a
shared one. Each node is declared with 2 CPUs (SlurmdParameters=config_overrides: the declared
count, whatever this machine has), so a task asking for 2 CPUs fills a node. Everything is made
here and removed by stop(): daemons, namespaces, veth pairs.
Debian's slurm-wlm 22.05, munge; root (slurmd and `ip netns`)."""
import os
import signal
import socket
import subprocess
import time

NODE_CPUS = 2  # declared per node: one twin run (nodelets: two lock-step threads) per node


def sh(*cmd):
    r = subprocess.run(list(cmd), capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError("%s failed (%d): %s" % (" ".join(cmd), r.returncode, (r.stderr or r.stdout).strip()))
    return r.stdout


def free_ports(n, lo=23100, hi=23999):
    """n ports free now on this host in [lo, hi) (below the ephemeral range, outside the sweep's
    ROS ports)."""
    out = []
    for p in range(lo, hi):
        with socket.socket() as s:
            try:
                s.bind(("0.0.0.0", p))
            except OSError:
                continue
        out.append(p)
        if len(out) == n:
            return out
    raise RuntimeError("no free ports in [%d, %d)" % (lo, hi))


def mem_mb():
    with open("/proc/meminfo") as f:
        kb = int(next(l for l in f if l.startswith("MemTotal:")).split()[1])
    return int(kb / 1024 * 0.9 / 2)  # the machine's memory shared by the two nodes


class Node:
    """One compute node: a network namespace linked to this host by a veth pair."""

    def __init__(self, index, tag, net):
        self.name = "hbtnode%d" % index
        self.ns = "hbts%s_n%d" % (tag, index)
        self.host_if, self.node_if = "hbs%sh%d" % (tag, index), "hbs%sn%d" % (tag, index)
        self.host_ip = "%s.%d" % (net, 4 * (index - 1) + 1)
        self.addr = "%s.%d" % (net, 4 * (index - 1) + 2)
        self.made = []  # what exists, for remove()

    def make(self):
        sh("ip", "netns", "add", self.ns)
        self.made.append("ns")
        sh("ip", "link", "add", self.host_if, "type", "veth", "peer", "name", self.node_if)
        self.made.append("veth")
        sh("ip", "link", "set", self.node_if, "netns", self.ns)
        sh("ip", "addr", "add", self.host_ip + "/30", "dev", self.host_if)
        sh("ip", "link", "set", self.host_if, "up")
        for cmd in (["ip", "link", "set", "lo", "up"], ["ip", "addr", "add", self.addr + "/30", "dev", self.node_if],
                    ["ip", "link", "set", self.node_if, "up"], ["ip", "route", "add", "default", "via", self.host_ip]):
            sh("ip", "netns", "exec", self.ns, *cmd)

    def netns_inode(self):
        return os.stat("/run/netns/%s" % self.ns).st_ino

    def remove(self):
        if "veth" in self.made:  # deleting one end deletes the pair (also done by deleting the ns)
            subprocess.run(["ip", "link", "del", self.host_if], capture_output=True)
        if "ns" in self.made:
            subprocess.run(["ip", "netns", "del", self.ns], capture_output=True)
        self.made = []

    def exists(self):
        """(namespace, host's veth end) still present."""
        ns = self.ns in subprocess.run(["ip", "netns", "list"], capture_output=True, text=True).stdout.split()
        link = subprocess.run(["ip", "link", "show", self.host_if], capture_output=True).returncode == 0
        return ns, link


class Cluster:
    """munged + slurmctld on this host, one slurmd per node in the node's namespaces; files in `d`."""

    def __init__(self, d, n_nodes=2):
        self.d, self.procs, self.stopped = d, [], []
        tag = str(os.getpid())
        net = "10.214.%d" % (os.getpid() % 250)
        self.nodes = [Node(i + 1, tag, net) for i in range(n_nodes)]
        self.ctld_addr = self.nodes[0].host_ip
        for sub in ("munge", "state", "spool", "log"):
            os.makedirs(os.path.join(d, sub), exist_ok=True)
        os.chmod(d, 0o755)
        os.chmod(os.path.join(d, "munge"), 0o755)
        self.key = os.path.join(d, "munge", "munge.key")
        with open(self.key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(self.key, 0o400)
        self.socket = os.path.join(d, "munge", "munge.socket")
        self.jobcomp = os.path.join(d, "log", "jobcomp.txt")
        self.ctld_port, self.slurmd_port = free_ports(2)
        self.conf = os.path.join(d, "slurm.conf")
        with open(self.conf, "w") as f:
            f.write(self.conf_text())
        self.env = dict(os.environ, SLURM_CONF=self.conf)

    def conf_text(self):
        d = self.d
        lines = ["ClusterName=hbtsweep",
                 "SlurmctldHost=localhost(%s)" % self.ctld_addr,
                 "SlurmctldPort=%d" % self.ctld_port,
                 "SlurmdPort=%d" % self.slurmd_port,  # the same on every node: each has its own addresses
                 "AuthType=auth/munge",
                 "CredType=cred/munge",
                 "AuthInfo=socket=%s" % self.socket,
                 "SlurmUser=root",
                 "SlurmdUser=root",
                 "StateSaveLocation=%s/state" % d,
                 "SlurmdSpoolDir=%s/spool/%%n" % d,
                 "SlurmctldPidFile=%s/slurmctld.pid" % d,
                 "SlurmdPidFile=%s/spool/slurmd_%%n.pid" % d,
                 "SlurmctldLogFile=%s/log/slurmctld.log" % d,
                 "SlurmdLogFile=%s/log/slurmd_%%n.log" % d,
                 "SlurmdParameters=config_overrides",
                 "ProctrackType=proctrack/linuxproc",
                 "TaskPlugin=task/none",
                 "SwitchType=switch/none",
                 "MpiDefault=none",
                 "SelectType=select/cons_tres",
                 "SelectTypeParameters=CR_CPU",
                 "AccountingStorageType=accounting_storage/none",
                 "JobAcctGatherType=jobacct_gather/none",
                 "JobCompType=jobcomp/filetxt",  # one line per finished job: its node list
                 "JobCompLoc=%s" % self.jobcomp,
                 "ReturnToService=2",
                 "MinJobAge=30"]
        for n in self.nodes:
            lines.append("NodeName=%s NodeHostname=%s NodeAddr=%s CPUs=%d RealMemory=%d State=UNKNOWN"
                         % (n.name, n.name, n.addr, NODE_CPUS, mem_mb()))
        lines.append("PartitionName=hbt Nodes=%s Default=YES MaxTime=INFINITE State=UP"
                     % ",".join(n.name for n in self.nodes))
        return "\n".join(lines) + "\n"

    def _start(self, name, cmd):
        log = open(os.path.join(self.d, "log", name + ".out"), "w")
        p = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env=self.env, start_new_session=True)
        log.close()  # the daemon holds its own copy
        self.procs.append((name, p))
        return p

    def start(self):
        for n in self.nodes:
            n.make()
            os.makedirs(os.path.join(self.d, "spool", n.name), exist_ok=True)
        m = os.path.join(self.d, "munge")
        self._start("munged", ["munged", "-F", "--key-file=" + self.key, "--socket=" + self.socket,
                               "--pid-file=%s/munged.pid" % m, "--log-file=%s/munged.log" % m,
                               "--seed-file=%s/munged.seed" % m])
        self._wait(lambda: os.path.exists(self.socket), "munged socket")
        self._start("slurmctld", ["slurmctld", "-D", "-i", "-f", self.conf])
        # in the node's network namespace, with its own hostname (UTS namespace); nsenter, not `ip
        # netns exec`, which mounts a sysfs of its own without /sys/fs/cgroup (slurmd needs it)
        for n in self.nodes:
            self._start("slurmd_" + n.name, [
                "nsenter", "--net=/run/netns/" + n.ns, "unshare", "--uts", "sh", "-c",
                'hostname "$0" && exec slurmd -D -N "$0" -f "$1"', n.name, self.conf])
        self._wait(self.all_idle, "nodes %s idle" % ", ".join(n.name for n in self.nodes))

    def node_states(self):
        r = subprocess.run(["sinfo", "-h", "-N", "-o", "%N %T"], env=self.env, capture_output=True, text=True)
        return dict(l.split() for l in r.stdout.splitlines() if len(l.split()) == 2)

    def all_idle(self):
        s = self.node_states()
        return all(s.get(n.name) == "idle" for n in self.nodes)

    def _wait(self, ok, what, timeout_s=60):
        t0 = time.time()
        while time.time() - t0 < timeout_s:
            for name, p in self.procs:
                if p.poll() is not None:
                    raise RuntimeError("%s exited (%d) while waiting for %s: %s" % (name, p.returncode, what, self.logs()))
            if ok():
                return
            time.sleep(0.5)
        raise RuntimeError("timeout waiting for %s: %s" % (what, self.logs()))

    def jobs_completed(self):
        """Slurm's own record of each finished job (jobcomp/filetxt): [{field: value}]."""
        if not os.path.exists(self.jobcomp):
            return []
        with open(self.jobcomp) as f:
            return [dict(kv.split("=", 1) for kv in line.split() if "=" in kv) for line in f if line.strip()]

    def logs(self):
        out = []
        for f in sorted(os.listdir(os.path.join(self.d, "log"))):
            with open(os.path.join(self.d, "log", f), errors="replace") as fh:
                out.append("--- %s\n%s" % (f, fh.read()[-2000:]))
        return "\n".join(out)

    def stop(self):
        """Stops the daemons (slurmd, slurmctld, munged), then removes the namespaces and veths."""
        for name, p in reversed(self.procs):
            if p.poll() is None:
                p.send_signal(signal.SIGTERM)
                try:
                    p.wait(timeout=20)
                except subprocess.TimeoutExpired:
                    p.kill()
                    p.wait()
            self.stopped.append((name, p.pid))
        self.procs = []
        for n in self.nodes:
            n.remove()
