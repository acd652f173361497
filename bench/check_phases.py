#!/usr/bin/env python3
# check_phases.py PERF_SCRIPT_OUTPUT: the phases of `cemv check` (docs/performance.md, "One solver per
# cone group's re-checks")
# and their share of the samples, from `perf record --call-graph dwarf build/cemv check ...` then
# `perf script -F comm,tid,ip,sym > out.txt`. Each sample goes to the first phase its stack names.
import sys, collections
# Reads `perf script -F comm,tid,ip,sym` output; classifies each sample by phase.
rules = [  # (phase, list of substrings that must be in stack (any), checked in order; first match wins)
 ("support: group core query (group_support_cores)", ["group_support_cores"]),
 ("support: member core on own encoding (own_core)", ["PropertyChecker::own_core"]),
 ("support: re-check on smaller matrix (core_support recheck_proof)", ["core_support", "!prove_on"]),
 ("support: engines on smaller matrix (prove_on)", ["prove_on"]),
 ("support: other (find_support)", ["find_support"]),
 ("group: random runs", ["ConeGroup::random_runs"]),
 ("group: k-induction proofs (prove_each)", ["ConeGroup::prove"]),
 ("group: shallow BMC (reach_each)", ["ConeGroup::reach"]),
 ("group: re-check (fresh solver)", ["ConeGroup::recheck"]),
 ("group: encode+reduce", ["encode_group"]),
 ("group: other", ["ConeGroup::decide"]),
 ("member: replay early run (answered_by_run)", ["answered_by_run"]),
 ("member: portfolio shrink cex", ["shrink_trace"]),
 ("member: portfolio re-check", ["Portfolio::confirmed"]),
 ("member: portfolio localized PDR", ["localized_attempt"]),
 ("member: portfolio quick k-ind", ["quick_attempt"]),
 ("member: portfolio engines", ["one_after_another"]),
 ("member: portfolio encode/reduce/other", ["Portfolio::"]),
 ("member: confirm trace on runtime", ["confirm_trace"]),
 ("member: other decide", ["PropertyChecker::decide"]),
 ("vacuity pass", ["lambda(unsigned long)#3", "settle_vacuity", "PropertyChecker::vacuity"]),
 ("support pass other", ["lambda(unsigned long)#4"]),
 ("decide pass other", ["lambda(unsigned long)#2"]),
 ("check_properties other", ["check_properties"]),
]
def classify(stack):
    s = "\n".join(stack)
    for name, pats in rules:
        pos = [p for p in pats if not p.startswith("!")]
        neg = [p[1:] for p in pats if p.startswith("!")]
        if any(p in s for p in pos) and not any(n in s for n in neg):
            return name
    return "outside check (parse, report, startup)"
counts = collections.Counter(); extra = collections.Counter()
stack = []; total = 0
def flush():
    global total
    if stack:
        total += 1
        counts[classify(stack)] += 1
        s = "\n".join(stack)
        for k in ["Z3_mk_context_rc", "Z3_del_context", "reduce_with", "encoder::encode", "Pdr::prove", "check_within"]:
            if k in s: extra[k] += 1
for line in open(sys.argv[1]):
    if not line.strip():
        flush(); stack = []
    elif line.startswith("\t") or line.startswith(" "):
        stack.append(line.strip())
flush()
for k, v in sorted(counts.items(), key=lambda x: -x[1]):
    print(f"{100*v/total:5.1f}%  {v:5d}  {k}")
print("total samples", total)
for k, v in extra.items(): print(f"  across phases: {k} {100*v/total:.1f}%")
