"""Console filter of `twin run`: passes roslaunch's output through unchanged (progress lines
included, segment by segment) except the lines roslaunch prints when the master stepper ends a
run normally by exiting as a required node ("REQUIRED process [stepper-N] has died!", "Initiating
shutdown!", the ===== rules around them). The full output stays in DIR/roslaunch.log; a failed run
is still reported loudly by the stepper ("run aborted: <participant>: ...") and by twin."""
import os
import re
import sys

DROP = re.compile(rb"(REQUIRED process \[stepper(-\d+)?\] has died!|^(\x1b\[[0-9;]*m)*Initiating shutdown!"
                  rb"|^(\x1b\[[0-9;]*m)*=+(\x1b\[[0-9;]*m)*$|process has died \[pid \d+, exit code 0, cmd .*stepper)")


def main():
    fd_in, out = sys.stdin.fileno(), sys.stdout.buffer
    seg = b""
    while True:
        chunk = os.read(fd_in, 4096)
        if not chunk:
            break
        for piece in re.split(rb"(\r|\n)", chunk):
            if piece in (b"\r", b"\n"):
                if not (piece == b"\n" and DROP.search(seg.strip())):
                    out.write(seg + piece)
                seg = b""
            else:
                seg += piece
        out.flush()
    out.write(seg)
    out.flush()


if __name__ == "__main__":
    main()
