#!/usr/bin/python3
"""Relative differences serial against 2 ranks from the logs of
test/Alltest -keep (its compareLast lines: 'PASS NAME: serial [...], np 2
[...], relative difference X'), as csv on stdout."""
import glob
import os
import re
import sys

line = re.compile(r'^(PASS|FAIL) (\S+): serial .*relative difference (\S+)$')
print('test,quantity,relative_difference')
for log in sorted(glob.glob(os.path.join(sys.argv[1], 'log.parallel-*'))):
    test = os.path.basename(log)[len('log.'):]
    for text in open(log):
        m = line.match(text.strip())
        if m:
            print('%s,%s,%s' % (test, m.group(2), m.group(3)))
