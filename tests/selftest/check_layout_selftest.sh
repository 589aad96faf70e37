#!/bin/sh
# The self-test of tests/check_layout.sh (one line of tests/selftest/selftest.sh,
# make test-runner). On a copy of src/ and include/ the check must give the
# real tree's result, word for word. Then files planted in a second copy
# (checked, never compiled) break each rule once: an include and symbols of
# a higher module, a base symbol with one user and one with none, a graph
# prototype defined in presets, a macro in two modules. They also hold
# traps the check must not fall into: names of a higher module as members
# (s->name), macro parameters and locals, a file's own macro and static, a
# comment and a string, an include guard; a base symbol with two users.
# Each break must be named, nothing else added to the tree's own problems,
# exit status 1. Prints ok/FAIL lines; exit status 0 when all pass.
# CHECK=another checker shows this test failing.
B=${B:-build}
CHECK=${CHECK:-tests/check_layout.sh}
t=$B/selftest/layout
rm -rf "$t" && mkdir -p "$t/same" "$t/bad" || exit 1
cp -R src include "$t/same/" && cp -R src include "$t/bad/" || exit 1
fail=0
check() { # what, condition
    if eval "$2"; then echo "  ok   $1"; else echo "  FAIL $1"; fail=$((fail + 1)); fi
}

sh "$CHECK" >"$t/real.out" 2>&1
real=$?
sh "$CHECK" "$t/same" >"$t/same.out" 2>&1
same=$?
check "check_layout.sh: a copy of the tree gives the tree's result (exit $real)" \
    '[ "$same" = "$real" ] && cmp -s "$t/real.out" "$t/same.out"'

r=$t/bad
cat >"$r/src/selftest_base.h" <<'EOF'
#ifndef SELFTEST_BASE_H
#define SELFTEST_BASE_H
#define SELFTEST_BASE_ONE 1
#define SELFTEST_BASE_NONE 2
#define SELFTEST_BASE_TWO 3
#endif
EOF
cat >"$r/src/engine/selftest_engine.h" <<'EOF'
#ifndef SELFTEST_ENGINE_H
#define SELFTEST_ENGINE_H
#define SELFTEST_ENGINE_MACRO 1
#define SELFTEST_IN_COMMENT 2
#define SELFTEST_LOCAL 3
#define SELFTEST_M(selftest_param) ((selftest_param) + 1)
typedef struct { int selftest_member; } selftest_engine_t;
int selftest_engine_fn(int selftest_arg);
int selftest_name(void);
static inline int selftest_static(void) { return SELFTEST_M(0); }
#endif
EOF
cat >"$r/src/engine/selftest_engine.c" <<'EOF'
#include "selftest_engine.h"
int selftest_engine_fn(int selftest_arg) { return selftest_arg + selftest_static() + selftest_name(); }
EOF
cat >"$r/src/pixel/selftest_pixel.c" <<'EOF'
#include "selftest_engine.h"
/* SELFTEST_IN_COMMENT */
#define SELFTEST_LOCAL 4
#define SELFTEST_PX(selftest_name) ((selftest_name) + SELFTEST_LOCAL)
static int selftest_static(void) { return 0; }
int selftest_pixel_fn(struct selftest_s *s)
{
    const char *m = "SELFTEST_IN_COMMENT";
    int selftest_member = 1, selftest_param = 2, selftest_arg = 3;
    (void)m;
    return SELFTEST_PX(s->selftest_name) + s->next.selftest_name + selftest_member + selftest_param +
           selftest_arg + selftest_static() + SELFTEST_BASE_TWO;
}
int selftest_pixel_bad(void) { return SELFTEST_ENGINE_MACRO + selftest_engine_fn(0); }
EOF
cat >"$r/src/kernels/selftest_kernels.c" <<'EOF'
int selftest_kernels_fn(int selftest_arg) { return selftest_arg + SELFTEST_ENGINE_MACRO + SELFTEST_BASE_TWO; }
EOF
cat >"$r/src/kernels/selftest_kernels.h" <<'EOF'
#define SELFTEST_DUP 1
EOF
cat >"$r/src/graph/selftest_graph.h" <<'EOF'
void selftest_decl(void);
EOF
cat >"$r/src/graph/selftest_graph.c" <<'EOF'
int selftest_graph_fn(void) { return SELFTEST_BASE_ONE; }
EOF
cat >"$r/src/presets/selftest_presets.h" <<'EOF'
#define SELFTEST_DUP 2
EOF
cat >"$r/src/presets/selftest_presets.c" <<'EOF'
void selftest_decl(void) {}
EOF
cat >"$t/want" <<'EOF'
check-layout: src/pixel/selftest_pixel.c (pixel) includes selftest_engine.h (engine): a higher module
check-layout: src/pixel/selftest_pixel.c uses SELFTEST_ENGINE_MACRO (defined in engine, a higher module)
check-layout: src/pixel/selftest_pixel.c uses selftest_engine_fn (defined in engine, a higher module)
check-layout: src/kernels/selftest_kernels.c uses SELFTEST_ENGINE_MACRO (defined in engine, a higher module)
check-layout: SELFTEST_BASE_ONE in src/selftest_base.h is used only by graph: it belongs there
check-layout: SELFTEST_BASE_NONE in src/selftest_base.h is used by no module
check-layout: src/presets/selftest_presets.c defines selftest_decl, declared in src/graph/selftest_graph.h (graph): declared in the wrong module
check-layout: SELFTEST_DUP is defined in two modules: src/kernels/selftest_kernels.h (kernels) and src/presets/selftest_presets.h (presets)
EOF
sh "$CHECK" "$r" >"$t/bad.out" 2>&1
bad=$?
check "check_layout.sh: planted breaks exit 1" '[ "$bad" = 1 ]'
while IFS= read -r w; do
    check "check_layout.sh names: ${w#check-layout: }" 'grep -qxF "$w" "$t/bad.out"'
done <"$t/want"
# The tree's own problems and the planted ones, nothing else, then the count.
grep -v 'problem(s)$' "$t/real.out" | grep -v '^check-layout: [0-9]* core files' | cat - "$t/want" |
    sort >"$t/expect"
grep -v 'problem(s)$' "$t/bad.out" | sort >"$t/got"
n=$(grep -c . "$t/expect")
check "check_layout.sh: nothing else (no trap sprung), $n problem(s) in all" \
    'cmp -s "$t/expect" "$t/got" && tail -n 1 "$t/bad.out" | grep -qx "check-layout: $n problem(s)"'
[ "$fail" -eq 0 ] || { echo "  (outputs in $t)"; exit 1; }
