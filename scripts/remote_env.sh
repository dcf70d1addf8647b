#!/usr/bin/env bash
# roslaunch env-loader for participants started on another host (launch argument remote:=...,
# docs/multihost.md). roslaunch runs `remote_env.sh roslaunch -c ...` over SSH with
# ROS_MASTER_URI set to the master of the run; this script gives that command the ROS
# environment of this checkout (build/devel/setup.bash beside it: the same checkout path and
# ../shared on every host) and, unless ROS_IP or ROS_HOSTNAME is already set, the address other
# hosts reach this one by: the source address of this host's route to the master.
set -e
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SETUP="$REPO/build/devel/setup.bash"
[ -f "$SETUP" ] || { echo "remote_env.sh: $SETUP not found on $(hostname): build the twin there (scripts/twin setup)" >&2; exit 2; }
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
set +u
# shellcheck disable=SC1090
source "$SETUP"
export ROS_HOME="${ROS_HOME:-$REPO/build/ros_home}"
export ROSCONSOLE_FORMAT='[${severity}] [${node}]: ${message}'
if [ -z "$ROS_IP" ] && [ -z "$ROS_HOSTNAME" ]; then
  master_host="$(echo "$ROS_MASTER_URI" | sed -E 's#^[a-z]+://\[?([^]/:]+)\]?(:[0-9]+)?/?.*#\1#')"
  master_ip="$(getent ahostsv4 "$master_host" | awk 'NR == 1 { print $1 }')"
  ROS_IP="$(ip -4 route get "${master_ip:-$master_host}" 2>/dev/null | sed -nE 's/.* src ([0-9.]+).*/\1/p')"
  [ -n "$ROS_IP" ] || { echo "remote_env.sh: no route from $(hostname) to the master $ROS_MASTER_URI" >&2; exit 2; }
  export ROS_IP
fi
exec "$@"
