#!/usr/bin/env python3
"""Copy of a case.yaml with section.key=value edits (keys replaced in place or added to their section); the
packing file is made absolute so every variant uses the original case's packing.
    python3 bench/case_edit.py SRC_CASE_YAML DST_CASE_YAML "sec.key=value[,sec.key=value...]" SRC_CASE_DIR
Used by bench/speed_vs_error.sh and bench/rank_ensemble.sh."""
import sys, re, os
src, dst, edits, case_dir = sys.argv[1:5]
lines = open(src).read().split('\n')
def set_key(sec, key, val):
    global lines
    try:
        s = lines.index(sec + ':')
    except ValueError:
        lines += [sec + ':']; s = len(lines) - 1
    e = s + 1
    while e < len(lines) and (lines[e].startswith(' ') or lines[e].strip() == ''):
        e += 1
    for i in range(s + 1, e):
        if re.match(r'\s+' + re.escape(key) + r':', lines[i]):
            lines[i] = '  %s: %s' % (key, val); return
    lines.insert(s + 1, '  %s: %s' % (key, val))
pf = 'generated/packing.csv'
for l in lines:
    m = re.match(r'\s+packing_file:\s*(\S+)', l)
    if m: pf = m.group(1)
set_key('ice', 'packing_file', os.path.join(case_dir, pf))
for e in filter(None, edits.split(',')):
    k, v = e.split('=', 1); sec, key = k.split('.', 1); set_key(sec, key, v)
open(dst, 'w').write('\n'.join(lines))
