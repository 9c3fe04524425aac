# Mesh every .poly in this folder, as many at a time as `make -j` allows:
#   make -f batch.mk -j2                 (DELTRI=path/to/deltri if it is not on PATH)
# A mesh is remade only when its .poly is newer; `make -k` goes on past a bad file.
DELTRI ?= deltri
SWITCHES ?= -pq30Q
# The meshes written here (name.1.poly) are not inputs.
POLYS := $(filter-out %.1.poly,$(wildcard *.poly))

all: $(POLYS:.poly=.1.ele)

%.1.ele: %.poly
	$(DELTRI) $(SWITCHES) $<

clean:
	rm -f $(POLYS:.poly=.1.node) $(POLYS:.poly=.1.ele) $(POLYS:.poly=.1.poly)

.PHONY: all clean
