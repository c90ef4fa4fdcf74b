#!/usr/bin/env bash
# A single-node Slurm on this machine, for testing the cluster path (tests/pipeline/test_slurm.py, .ci/run):
#
#   profiles/slurm/local-slurm.sh start   # as root; returns when sinfo shows the node idle
#   profiles/slurm/local-slurm.sh stop
#
# Needs Debian's slurmctld, slurmd and munge (apt-get install -y slurmctld slurmd munge); no systemd, no cgroups
# (proctrack/linuxproc, task/none) and no accounting database (accounting_storage/none: sacct has no history, so
# the profile's status command is squeue, which keeps finished jobs for MinJobAge seconds). Everything the
# script writes lives in one directory it owns, $LOCAL_SLURM_DIR (default /tmp/vibroadhesion-slurm): slurm.conf,
# a munge key and socket of its own, state, spool, logs and the PIDs of the three daemons it started, which
# `stop` kills (and nothing else). Both commands are idempotent. The daemons talk over 127.0.0.1 only.
# One thing outside that directory: /etc/slurm/slurm.conf, a symbolic link to its slurm.conf while the daemons
# run (made only where no such file exists, removed by `stop`), because the Slurm clients inside a job need the
# default path: snakemake-executor-plugin-slurm-jobstep 0.6.1 drops SLURM_CONF from the environment of its srun.
set -euo pipefail

DIR="${LOCAL_SLURM_DIR:-/tmp/vibroadhesion-slurm}"
CONF="$DIR/slurm.conf"
ETC_CONF=/etc/slurm/slurm.conf

alive() { [[ -f "$DIR/$1.pid" ]] && kill -0 "$(cat "$DIR/$1.pid")" 2>/dev/null; }

write_config() {
	# The node line as slurmd sees this machine (CPUs, sockets, cores, threads, RealMemory in MB).
	local node
	node="$(slurmd -C | head -n 1)"
	mkdir -p "$DIR"/{state,spool,log,munge}
	cat >"$CONF" <<EOF
# Written by profiles/slurm/local-slurm.sh: one node, no cgroups, no accounting database.
ClusterName=vibroadhesion
SlurmctldHost=$(hostname -s)(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=${LOCAL_SLURM_PORT:-6817}
SlurmdPort=$((${LOCAL_SLURM_PORT:-6817} + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$DIR/munge/munge.socket
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
MpiDefault=none
ReturnToService=2
MinJobAge=600
StateSaveLocation=$DIR/state
SlurmdSpoolDir=$DIR/spool
SlurmctldPidFile=$DIR/slurmctld.daemon.pid
SlurmdPidFile=$DIR/slurmd.daemon.pid
SlurmctldLogFile=$DIR/log/slurmctld.log
SlurmdLogFile=$DIR/log/slurmd.log
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
	# munged wants its socket's directory searchable by all, and its key readable by munge alone.
	chown munge:munge "$DIR/munge"
	chmod 0755 "$DIR/munge"
	if [[ ! -f "$DIR/munge/munge.key" ]]; then
		dd if=/dev/urandom of="$DIR/munge/munge.key" bs=1024 count=1 status=none
	fi
	chown munge:munge "$DIR/munge/munge.key"
	chmod 0400 "$DIR/munge/munge.key"
}

# Start one daemon in the foreground mode of its own (-F, -D) in the background and record its PID.
launch() {
	local name="$1"
	shift
	setsid "$@" >"$DIR/log/$name.out" 2>&1 </dev/null &
	echo $! >"$DIR/$name.pid"
}

wait_idle() {
	local state=""
	for _ in $(seq 60); do
		state="$(SLURM_CONF="$CONF" timeout 5 sinfo -h -N -o %t 2>/dev/null || true)"
		[[ "$state" == idle ]] && return 0
		sleep 1
	done
	echo "local-slurm: the node is '${state:-not reported}' after 60 s; see $DIR/log/" >&2
	return 1
}

start() {
	if [[ "$(id -u)" != 0 ]]; then
		echo "local-slurm: start needs root (slurmd runs jobs as their users)" >&2
		return 1
	fi
	if alive munged && alive slurmctld && alive slurmd && [[ "$(readlink "$ETC_CONF" || true)" == "$CONF" ]]; then
		wait_idle
		echo "local-slurm: node idle ($CONF)"
		return 0
	fi
	stop
	if [[ -e "$ETC_CONF" || -L "$ETC_CONF" ]]; then
		echo "local-slurm: $ETC_CONF exists: this machine has a Slurm configuration of its own; not touching it" >&2
		return 1
	fi
	write_config
	mkdir -p "$(dirname "$ETC_CONF")"
	ln -s "$CONF" "$ETC_CONF"
	launch munged setpriv --reuid=munge --regid=munge --init-groups /usr/sbin/munged -F \
		--key-file="$DIR/munge/munge.key" --socket="$DIR/munge/munge.socket" \
		--pid-file="$DIR/munge/munged.pid" --seed-file="$DIR/munge/munged.seed" --log-file="$DIR/munge/munged.log"
	for _ in $(seq 20); do
		[[ -S "$DIR/munge/munge.socket" ]] && break
		sleep 0.5
	done
	launch slurmctld /usr/sbin/slurmctld -D -i -f "$CONF"
	launch slurmd /usr/sbin/slurmd -D -f "$CONF"
	wait_idle
	echo "local-slurm: node idle ($CONF)"
}

stop() {
	local name pid
	for name in slurmd slurmctld munged; do
		[[ -f "$DIR/$name.pid" ]] || continue
		pid="$(cat "$DIR/$name.pid")"
		if kill -0 "$pid" 2>/dev/null; then
			kill "$pid"
			for _ in $(seq 20); do
				kill -0 "$pid" 2>/dev/null || break
				sleep 0.5
			done
			kill -0 "$pid" 2>/dev/null && kill -9 "$pid"
		fi
		rm -f "$DIR/$name.pid"
	done
	if [[ "$(readlink "$ETC_CONF" || true)" == "$CONF" ]]; then
		rm -f "$ETC_CONF"
	fi
}

case "${1:-}" in
start) start ;;
stop) stop ;;
*)
	echo "usage: $0 start|stop" >&2
	exit 2
	;;
esac
