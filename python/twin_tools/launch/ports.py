"""Master ports for runs started by the tools (twin sweep, the tests' run_util, twin bench soak).
A port comes from a range below the kernel's ephemeral ports, so no bind(0) of another program --
roslaunch's own XML-RPC server among them -- can take it between the choice and the master's
start; it is locked with flock on /tmp/hbt_ros_ports/<port>.lock for as long as the caller keeps
the lock's fd open (no other run on this machine picks it) and must be free when chosen.

  python3 -m twin_tools.launch.ports pick SEED   prints "PORT LOCKFILE": a port of the range that
      is free and unlocked now, starting the search at SEED (scripts/twin run then takes the lock
      itself with flock, and picks again if another run took it first)."""
import fcntl
import os
import socket
import sys

PORT_LO, PORT_HI = 21000, 23000  # [port) range for the runs' masters (ephemeral ports start at 32768)
LOCK_DIR = "/tmp/hbt_ros_ports"


def reserve_port(first):
    """(port, lock fd): a free port of the range, locked for this process until the fd is closed."""
    os.makedirs(LOCK_DIR, exist_ok=True)
    try:
        os.chmod(LOCK_DIR, 0o1777)
    except OSError:
        pass
    n = PORT_HI - PORT_LO
    for k in range(n):
        port = PORT_LO + (first + k) % n
        fd = os.open(os.path.join(LOCK_DIR, "%d.lock" % port), os.O_CREAT | os.O_RDWR, 0o666)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            os.close(fd)
            continue
        with socket.socket() as s:
            try:
                s.bind(("", port))
                return port, fd
            except OSError:
                pass
        os.close(fd)
    raise RuntimeError("no free port in [%d, %d)" % (PORT_LO, PORT_HI))


def main(argv):
    if len(argv) != 3 or argv[1] != "pick" or not argv[2].isdigit():
        sys.exit(__doc__)
    port, fd = reserve_port(int(argv[2]))
    os.close(fd)  # the caller locks it for the run's life
    print(port, os.path.join(LOCK_DIR, "%d.lock" % port))


if __name__ == "__main__":
    main(sys.argv)
