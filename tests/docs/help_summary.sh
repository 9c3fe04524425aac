#!/bin/sh
# The manual's switch summary is deltri -h's output, word for word.
# usage: help_summary.sh DELTRI MANUAL
"$1" -h > help.txt || exit 1
# The lines between the summary's opening fence and its closing one.
awk '/^Summary \(from `deltri -h`\):/ {found = 1; next}
     found && /^```$/ {if (inside) exit; inside = 1; next}
     inside {print}' "$2" > manual-help.txt
diff -u help.txt manual-help.txt && echo 'the manual shows deltri -h as it is'
