#!/bin/sh
# The library holds no global mutable state: every object in the writable sections of
# libdeltri.so (.data, .bss, .tdata, .tbss; objdump -t) must be one of the immutable ones listed
# here with the reason, or the C runtime's own. A new static variable anywhere in the library fails
# this test until it is removed or argued for here.
#   global_state.sh LIBDELTRI_SO
set -u
lib=$1
command -v objdump >/dev/null && command -v c++filt >/dev/null ||
  { echo "SKIP: missing objdump, c++filt; install with: sudo apt-get install -y binutils"; exit 77; }
objects=$(objdump -t "$lib" | awk '$0 ~ / (\.data|\.bss|\.tdata|\.tbss)[ \t]/ && $3 == "O" { print $NF }' | c++filt | LC_ALL=C sort -u)
unexpected=$(printf '%s\n' "$objects" | grep -v -x \
  -e 'completed.0' -e '__dso_handle' -e '__TMC_END__' -e 'DW.ref.*' \
  `# constexpr tables of the switches (options/switch_table.cpp): const, in .data only because they hold pointers` \
  -e 'deltri::(anonymous namespace)::kTable' -e 'deltri::(anonymous namespace)::kLongOptions' \
  `# a function-local static const bool, set once by the language's thread-safe initialisation (io/decimal_parse.h)` \
  -e 'deltri::decimal::parse_double(char const\*, char const\*, double&, char const\*\*)::precise' \
  -e 'guard variable for deltri::decimal::parse_double(char const\*, char const\*, double&, char const\*\*)::precise')
if [ -n "$unexpected" ]; then
  echo "FAIL: writable objects in $lib that are not known to be immutable:"
  printf '  %s\n' "$unexpected"
  exit 1
fi
echo "libdeltri.so: $(printf '%s\n' "$objects" | wc -l) objects in writable sections, every one immutable or the C runtime's"
