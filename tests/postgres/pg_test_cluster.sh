#!/bin/bash
# A throw-away PostgreSQL cluster for the tests of the server store
# (docs/lab-store.md, "The test cluster"); the ctest fixture pg_cluster.
#
#   pg_test_cluster.sh start STATE_DIR    initdb + start on 127.0.0.1, a free port
#   pg_test_cluster.sh stop STATE_DIR     stop it and delete it
#   pg_test_cluster.sh stop-server STATE_DIR / start-server STATE_DIR
#                                         what a test of a server restart calls
#
# STATE_DIR/url receives postgresql://driftlab@127.0.0.1:PORT (append /DB);
# the tests read it. When the cluster cannot be had (no PostgreSQL 15
# binaries, or root without a postgres user), STATE_DIR/skip says why and the
# tests skip with that reason. The cluster runs as an unprivileged user: the
# caller, or `postgres` when the caller is root (PostgreSQL refuses root).
set -u
cmd=${1:?start|stop|stop-server|start-server}
state=${2:?STATE_DIR}
bin=${DRIFTLAB_PG_BIN:-/usr/lib/postgresql/15/bin}

as_owner() {
    if [ "$(id -u)" = 0 ]; then runuser -u postgres -- "$@"; else "$@"; fi
}

pgctl() {
    as_owner "$bin/pg_ctl" -D "$(cat "$state/cluster")/data" "$@"
}

case "$cmd" in
start)
    rm -rf "$state"
    mkdir -p "$state"
    if [ ! -x "$bin/initdb" ] || [ ! -x "$bin/pg_ctl" ]; then
        echo "no PostgreSQL server binaries in $bin (Debian: postgresql-15)" >"$state/skip"
        exit 0
    fi
    if [ "$(id -u)" = 0 ] && ! id postgres >/dev/null 2>&1; then
        echo "running as root and there is no 'postgres' user to run the server as" >"$state/skip"
        exit 0
    fi
    cluster=$(mktemp -d /tmp/driftlab-pg-XXXXXX) || exit 1
    echo "$cluster" >"$state/cluster"
    [ "$(id -u)" = 0 ] && chown postgres "$cluster"
    port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
    echo "$port" >"$state/port"
    as_owner "$bin/initdb" -D "$cluster/data" -U driftlab -A trust -E UTF8 --no-locale \
        >"$cluster/initdb.log" 2>&1 || { cat "$cluster/initdb.log"; exit 1; }
    # fsync off: a throw-away cluster, and the tests measure no durability of its disk.
    pgctl -w -l "$cluster/server.log" \
        -o "-p $port -k $cluster -h 127.0.0.1 -c fsync=off -c max_connections=50" start \
        >/dev/null || { cat "$cluster/server.log"; exit 1; }
    echo "postgresql://driftlab@127.0.0.1:$port" >"$state/url"
    echo "test cluster on 127.0.0.1:$port in $cluster"
    ;;
stop)
    if [ -f "$state/cluster" ]; then
        cluster=$(cat "$state/cluster")
        pgctl -m immediate stop >/dev/null 2>&1
        rm -rf "$cluster"
    fi
    rm -rf "$state"
    ;;
stop-server)
    pgctl -m fast -w stop >/dev/null
    ;;
start-server)
    cluster=$(cat "$state/cluster")
    port=$(cat "$state/port")
    pgctl -w -l "$cluster/server.log" \
        -o "-p $port -k $cluster -h 127.0.0.1 -c fsync=off -c max_connections=50" start >/dev/null
    ;;
*)
    echo "unknown command $cmd" >&2
    exit 2
    ;;
esac
