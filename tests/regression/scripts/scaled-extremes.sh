#!/bin/sh
# Issue 17, randomized: the corpus scaled and translated into the subnormal and near-overflow
# ranges (2^-1070, 2^1000, mixed), each mesh checked by an exact rational checker that shares
# nothing with deltri's predicates (tests/tools/scaled_extremes.py). One fixed seed, then one
# random seed (printed, to replay a failure: scaled_extremes.py DELTRI data SEED).
#   scaled-extremes.sh DELTRI
set -u
deltri=$1
here=$(cd "$(dirname "$0")" && pwd)
root=$here/../../..
status=0
/usr/bin/python3 "$root/tests/tools/scaled_extremes.py" "$deltri" "$root/data" 17 || status=1
/usr/bin/python3 "$root/tests/tools/scaled_extremes.py" "$deltri" "$root/data" || status=1
exit $status
