# Helpers for whole-process timings on the shared, noisy 2-core machines, sourced by
# tools/batch_throughput.sh and tools/pyrender_peer.sh.

# The median of the numbers on stdin, one a line.
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

# Jiffies all CPUs have spent busy since boot (user, nice, system, irq, softirq, steal).
busy_jiffies() { awk '/^cpu / {print $2 + $3 + $4 + $7 + $8 + $9}' /proc/stat; }

# Waits (at most a minute) until the CPUs were at least 95 % idle over the last half second.
wait_for_idle() {
  local a b tries=0
  while [ $tries -lt 120 ]; do
    a=$(awk '/^cpu / {print $5 + $6, $2 + $3 + $4 + $5 + $6 + $7 + $8 + $9}' /proc/stat)
    sleep 0.5
    b=$(awk '/^cpu / {print $5 + $6, $2 + $3 + $4 + $5 + $6 + $7 + $8 + $9}' /proc/stat)
    [ "$(echo "$a $b" | awk '{print (($3 - $1) >= 0.95 * ($4 - $2))}')" = 1 ] && return
    tries=$((tries + 1))
  done
}
