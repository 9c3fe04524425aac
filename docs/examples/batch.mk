# Mesh every input .poly in this folder, as many at a time as `make -j` allows:
#   make -f batch.mk -j2                 (DELTRI=path/to/deltri if it is not on PATH)
# Each run writes a JSON report, name.poly.json, listing the files it wrote; batch-inputs.sh (next
# to this file) reads those lists to tell deltri's outputs from inputs, so a Triangle output kept as
# an input (box.1.poly beside box.poly) is never meshed over or cleaned away.
# A mesh is remade only when its .poly is newer than its report; `make -k` goes on past a bad file.
DELTRI ?= deltri
SWITCHES ?= -pq30Q
HERE := $(dir $(lastword $(MAKEFILE_LIST)))
ifneq ($(MAKECMDGOALS),clean)
INPUTS := $(shell sh '$(HERE)batch-inputs.sh')
endif

all: $(INPUTS:=.json)

%.poly.json: %.poly
	$(DELTRI) $(SWITCHES) --json=$@ $<

# Only what the reports say deltri wrote, the reports included.
clean:
	sh '$(HERE)batch-inputs.sh' --outputs | while IFS= read -r f; do rm -f -- "$$f"; done

.PHONY: all clean
