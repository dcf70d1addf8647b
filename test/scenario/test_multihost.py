#!/usr/bin/python3
"""Multi-host run on one machine: the engine participant runs on a second "host" -- a network
namespace made by this test, reached over a veth pair with addresses made by the test -- started
there by roslaunch over SSH (launch arguments remote:=engine remote_host:=..., README "Multi-host
runs"), while the stepper, recorder and the other participants stay on this host. The run must
give the same bag (every lock-step message, byte for byte) and the same summary.json (except
the wall time) as the one-host run of the same scenario; and the engine must really have run in
the namespace (its process's network namespace is the test's). Needs root (ip netns), sshd and
paramiko (installed by `scripts/twin test`); skipped with the reason otherwise.

The default run binds every socket to loopback (twin sets ROS_IP=127.0.0.1): checked too."""
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import unittest

from twin_tools.launch import run_util

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
TWIN = os.path.join(REPO, "scripts", "twin")

UNTIL = "30"


def sh(*cmd, **kw):
    return subprocess.run(list(cmd), check=True, capture_output=True, text=True, **kw)


def missing_prerequisite():
    if os.geteuid() != 0:
        return "needs root (ip netns, veth)"
    for tool in ("/usr/sbin/ip", "/usr/sbin/sshd", "/usr/bin/ssh-keygen"):
        if not os.path.exists(tool):
            return "%s not installed (scripts/twin test installs openssh-server, iproute2)" % tool
    try:
        import paramiko  # noqa: F401  roslaunch's SSH client
    except ImportError:
        return "python3-paramiko not installed (scripts/twin test installs it)"
    return None


class TwoHosts:
    """A network namespace with sshd, linked to this host by a veth pair (a /30 of its own)."""

    def __init__(self, tmp):
        pid = os.getpid()
        self.ns, self.va, self.vb = "hbt%d" % pid, "hbta%d" % pid, "hbtb%d" % pid
        net = "10.213.%d" % (pid % 250)
        self.host_ip, self.remote_ip = net + ".1", net + ".2"
        self.tmp = tmp
        self.home = os.path.join(tmp, "home")
        self.sshd = None

    def up(self):
        sh("ip", "netns", "add", self.ns)
        sh("ip", "link", "add", self.va, "type", "veth", "peer", "name", self.vb)
        sh("ip", "link", "set", self.vb, "netns", self.ns)
        sh("ip", "addr", "add", self.host_ip + "/30", "dev", self.va)
        sh("ip", "link", "set", self.va, "up")
        for cmd in (["ip", "addr", "add", self.remote_ip + "/30", "dev", self.vb],
                    ["ip", "link", "set", self.vb, "up"], ["ip", "link", "set", "lo", "up"]):
            sh("ip", "netns", "exec", self.ns, *cmd)
        # SSH: a host key and a client key made here; roslaunch (paramiko) reads ~/.ssh of HOME
        ssh_dir = os.path.join(self.home, ".ssh")
        os.makedirs(ssh_dir, mode=0o700)
        host_key, client_key = os.path.join(self.tmp, "host_key"), os.path.join(ssh_dir, "id_ed25519")
        sh("ssh-keygen", "-q", "-t", "ed25519", "-N", "", "-f", host_key)
        sh("ssh-keygen", "-q", "-t", "ed25519", "-N", "", "-f", client_key)
        with open(host_key + ".pub") as f:
            host_pub = " ".join(f.read().split()[:2])
        with open(os.path.join(ssh_dir, "known_hosts"), "w") as f:
            f.write("%s %s\n" % (self.remote_ip, host_pub))
        with open(os.path.join(ssh_dir, "config"), "w") as f:
            f.write("Host %s\n  IdentityFile %s\n  User root\n" % (self.remote_ip, client_key))
        shutil.copy(client_key + ".pub", os.path.join(self.tmp, "authorized_keys"))
        os.makedirs("/run/sshd", exist_ok=True)  # sshd's privilege-separation directory
        self.sshd_log = open(os.path.join(self.tmp, "sshd.log"), "w")
        self.sshd = subprocess.Popen(
            ["ip", "netns", "exec", self.ns, "/usr/sbin/sshd", "-D", "-e", "-f", "/dev/null",
             "-h", host_key, "-o", "ListenAddress=" + self.remote_ip, "-o", "StrictModes=no",
             "-o", "AuthorizedKeysFile=" + os.path.join(self.tmp, "authorized_keys"),
             "-o", "PidFile=" + os.path.join(self.tmp, "sshd.pid"), "-o", "UsePAM=no",
             "-o", "PermitRootLogin=prohibit-password"],
            stdout=self.sshd_log, stderr=subprocess.STDOUT, start_new_session=True)
        t0 = time.time()
        while True:  # sshd listening on the remote address, reached through the veth pair
            try:
                socket.create_connection((self.remote_ip, 22), timeout=1).close()
                break
            except OSError:
                if time.time() - t0 > 20 or self.sshd.poll() is not None:
                    raise RuntimeError("sshd did not start in %s (see %s/sshd.log)" % (self.ns, self.tmp))
                time.sleep(0.2)

    def down(self):
        if self.sshd is not None and self.sshd.poll() is None:
            os.killpg(self.sshd.pid, signal.SIGTERM)
            self.sshd.wait(timeout=10)
        subprocess.run(["ip", "netns", "del", self.ns], capture_output=True)
        subprocess.run(["ip", "link", "del", self.va], capture_output=True)  # gone with the ns, normally


def twin_run(out, env, *args):
    r = subprocess.run([TWIN, "run", "baseline_urban", "--out", out, "until:=" + UNTIL, *args],
                       env=env, capture_output=True, text=True, timeout=600)
    return r


class MultiHost(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        why = missing_prerequisite()
        if why:
            raise unittest.SkipTest("multi-host test skipped: " + why)
        cls.tmp = tempfile.mkdtemp(prefix="hbt_multihost_")
        cls.hosts = TwoHosts(cls.tmp)
        try:
            cls.hosts.up()
            env = {k: v for k, v in os.environ.items() if k not in ("ROS_IP", "ROS_HOSTNAME", "ROS_MASTER_URI")}
            cls.one = os.path.join(cls.tmp, "one_host")
            marker = "HBT_MULTIHOST_TEST=%d" % os.getpid()  # inherited by every local process of the run
            watch = Watch(os.path.join(cls.tmp, "one_host.json"), marker)
            cls.r_one = twin_run(cls.one, dict(env, HBT_MULTIHOST_TEST=str(os.getpid())), "mode:=nodes")
            cls.procs_one = watch.stop()
            env_two = dict(env, ROS_IP=cls.hosts.host_ip, HOME=cls.hosts.home)
            cls.two = os.path.join(cls.tmp, "two_hosts")
            # the remote processes do not inherit this environment: they know the master by its address
            watch = Watch(os.path.join(cls.tmp, "two_hosts.json"), "ROS_MASTER_URI=http://%s:" % cls.hosts.host_ip)
            cls.r_two = twin_run(cls.two, env_two, "remote:=engine", "remote_host:=" + cls.hosts.remote_ip,
                                 "remote_user:=root")
            cls.procs_two = watch.stop()
        except Exception:
            cls.hosts.down()
            raise

    @classmethod
    def tearDownClass(cls):
        cls.hosts.down()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_both_runs_complete(self):
        self.assertEqual(self.r_one.returncode, 0, self.r_one.stdout[-3000:] + self.r_one.stderr[-3000:])
        self.assertEqual(self.r_two.returncode, 0, self.r_two.stdout[-3000:] + self.r_two.stderr[-3000:])

    def test_engine_ran_in_the_other_namespace(self):
        with open(os.path.join(self.two, "roslaunch.log")) as f:
            log = f.read()
        self.assertIn("remote[%s-0]: ssh connection created" % self.hosts.remote_ip, log)
        # /run/netns/<ns> is a bind mount of the namespace: its inode names it (net:[inode])
        remote_ns = "net:[%d]" % os.stat("/run/netns/%s" % self.hosts.ns).st_ino
        engines = [p for p in self.procs_two if p["comm"] == "engine_node"]
        self.assertTrue(engines, "no engine process seen during the two-host run")
        self.assertEqual({p["netns"] for p in engines}, {remote_ns})
        others = [p for p in self.procs_two if p["comm"] in ("stepper", "rosmaster")]
        self.assertTrue(others)
        self.assertNotIn(remote_ns, {p["netns"] for p in others})  # these stayed on this host

    def test_bag_bit_identical(self):
        a = [m for m in run_util.bag_messages(os.path.join(self.one, "run.bag")) if m[0] != "/twin/run_info"]
        b = [m for m in run_util.bag_messages(os.path.join(self.two, "run.bag")) if m[0] != "/twin/run_info"]
        # every topic every 0.1 s incl. t = 0
        self.assertEqual({m[0] for m in a}, set(run_util.BASELINE_TOPICS))
        self.assertEqual(len(a), len(run_util.BASELINE_TOPICS) * (int(UNTIL) * 10 + 1))
        self.assertEqual(a, b)

    def test_summary_identical(self):
        with open(os.path.join(self.one, "summary.json")) as f:
            a = json.load(f)
        with open(os.path.join(self.two, "summary.json")) as f:
            b = json.load(f)
        for s in (a, b):
            s.pop("wall_time_s")
        self.assertGreater(a["fuel_kg"], 0.0)
        self.assertEqual(a, b)

    def test_one_host_run_listens_on_loopback(self):
        """twin's default ROS_IP=127.0.0.1: the master, roslaunch's server and every node's
        TCPROS data server listen on loopback only; roscpp's XML-RPC slave server binds all
        interfaces whatever ROS_IP says (xmlrpcpp has no bind address) -- at most one per node,
        and it is advertised to the master as 127.0.0.1 (docs/multihost.md)."""
        by_comm = {}
        for p in self.procs_one:
            by_comm.setdefault(p["comm"], []).append(p)
        for comm in ("rosmaster", "stepper", "recorder", "vehicle_node", "engine_node"):
            self.assertIn(comm, by_comm, "process %s not seen; seen: %s" % (comm, sorted(by_comm)))
        for p in by_comm["rosmaster"]:
            self.assertTrue(p["listen"] and all(a.startswith("127.0.0.1:") for a in p["listen"]), p)
        for p in self.procs_one:
            wildcard = [a for a in p["listen"] if not a.startswith("127.")]
            if p["comm"] in ("nodelet", "stepper", "recorder", "vehicle_node", "engine_node",
                             "aftertreatment_", "cooling_node", "hvac_node", "rosout"):
                self.assertLessEqual(len(wildcard), 1, p)  # the XML-RPC slave server
                self.assertTrue(any(a.startswith("127.0.0.1:") for a in p["listen"]), p)  # TCPROS
            else:  # python: roslaunch, rosmaster, the scripts; nothing beyond loopback
                self.assertEqual(wildcard, [], p)


# Watches the processes of one run while it goes (argv[2]: a byte string their environment holds)
# and writes, as JSON to argv[1], for each: its command name, network namespace and the TCP
# addresses it listens on (ss -ltnp).
WATCH = r"""
import json, os, re, subprocess, sys, time
marker = sys.argv[2].encode()
seen = {}
end = time.time() + 600
while time.time() < end:
    listen = {}
    ss = subprocess.run(['ss', '-ltnpH'], capture_output=True, text=True).stdout
    for line in ss.splitlines():
        for pid in re.findall(r'pid=(\d+)', line):
            listen.setdefault(pid, set()).add(line.split()[3])
    for pid in os.listdir('/proc'):
        if not pid.isdigit():
            continue
        try:
            with open('/proc/%s/environ' % pid, 'rb') as f:
                if marker not in f.read():
                    continue
            with open('/proc/%s/comm' % pid) as f:
                comm = f.read().strip()
            # keyed by pid and command: a forked roslaunch child becomes a node when it execs
            p = seen.setdefault(pid + ':' + comm, {'comm': comm, 'netns': os.readlink('/proc/%s/ns/net' % pid),
                                                   'listen': []})
            p['listen'] = sorted(set(p['listen']) | listen.get(pid, set()))
        except OSError:
            pass
    with open(sys.argv[1] + '.tmp', 'w') as f:
        json.dump(seen, f)
    os.replace(sys.argv[1] + '.tmp', sys.argv[1])
    time.sleep(0.2)
"""


class Watch:
    def __init__(self, path, marker):
        self.path = path
        self.proc = subprocess.Popen([sys.executable, "-c", WATCH, path, marker], start_new_session=True)

    def stop(self):
        self.proc.kill()
        self.proc.wait()
        with open(self.path) as f:
            return list(json.load(f).values())


if __name__ == "__main__":
    run_util.unittest_main()  # all skipped (no root, sshd, ip): exit 77, ctest "Not Run"
