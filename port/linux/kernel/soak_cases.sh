# make test-linux's soak (sourced by run.sh; the guest side is soak() in
# init.sh, make soak-cam runs it alone with 20 000 frames): bloom_cam through
# rounds of faults (a flagged buffer, a disconnect, a 2 s stall) at
# pseudo-random intervals must keep streaming, count what happened, stop
# cleanly on SIGTERM, and hold its resources: descriptors and mappings the
# same at the end as after the first second, RSS no larger at the end than
# after the first round of faults (which runs each fault path once).
soak_checks() { # the soak (init.sh): frames, faults counted, resources
    t=$r/soak.txt
    tot=$(sed -n 's/^bloom_cam: total: \([0-9]*\) frames.*/\1/p' "$t" 2>/dev/null)
    nbad=$(sed -n 's/^bloom_cam: total: .*; [0-9]* skipped for newer (--latest), \([0-9]*\) bad .*/\1/p' "$t" 2>/dev/null)
    nrec=$(sed -n 's/^bloom_cam: total: .*, \([0-9]*\) reconnects$/\1/p' "$t" 2>/dev/null)
    inj=$(sed -n 's/^injected: //p' "$t" 2>/dev/null)
    set -- $(echo "$inj" | tr -c '0-9\n' ' ') 0 0 0 0; nf=$1; nd=$2; ns=$3
    if grep -q '^exit 0$' "$t" 2>/dev/null && grep -q 'bloom_cam: stopping on SIGTERM' "$t" &&
        [ "${tot:-0}" -ge "$SOAK_FRAMES" ] && [ "$nf" -ge 2 ] && [ "$nd" -ge 2 ] && [ "$ns" -ge 2 ] &&
        [ "${nbad:-0}" -ge 1 ] && [ "${nrec:-0}" -ge 2 ]; then
        ok "soak: $tot frames (wanted $SOAK_FRAMES), injected $inj; counted $nbad bad frames, $nrec reconnects; stopped by SIGTERM, exit 0"
    else
        bad "soak: wanted $SOAK_FRAMES frames, two rounds of faults counted, exit 0 (got ${tot:-no} frames, $nbad bad, $nrec reconnects; $inj)"
        grep -v ': last second: ' "$t" 2>/dev/null | sed 's/^/       /' | tail -n 40
    fi
    s0=$(cat "$r/soak-start.txt" 2>/dev/null); s1=$(cat "$r/soak-warm.txt" 2>/dev/null)
    s2=$(cat "$r/soak-end.txt" 2>/dev/null)
    get() { echo "$1" | sed -n "s/.*$2 \([0-9]*\).*/\1/p"; }
    # descriptors and mappings: the same at the end as after the first second
    for what in fds maps; do
        a=$(get "$s0" $what); b=$(get "$s2" $what)
        if [ -n "$a" ] && [ "$a" = "$b" ] && [ "$(get "$s1" $what)" = "$a" ]; then
            ok "soak: $what $a after the first second, after the first round of faults and at the end"
        else
            bad "soak: $what after the first second '$a', after a round '$(get "$s1" $what)', at the end '$b'"
        fi
    done
    # RSS: no growth from the first round of faults to the end (the first
    # round runs each fault path once, touching its code and buffers)
    a=$(get "$s0" rss); w=$(get "$s1" rss); b=$(get "$s2" rss)
    an="(anonymous $(get "$s0" anon), $(get "$s1" anon), $(get "$s2" anon) kB)"
    if [ -n "$a" ] && [ -n "$w" ] && [ -n "$b" ] && [ "$b" -le "$w" ]; then
        ok "soak: RSS $a kB after the first second, $w kB after the first round of faults, $b kB at the end $an"
    else
        bad "soak: RSS grew or unread: '$a' kB after the first second, '$w' kB after the first round, '$b' kB at the end $an"
    fi
}
