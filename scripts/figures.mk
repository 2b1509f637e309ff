# Included by `make reproduce-figures`: one target per figure, so that make -j runs figures side by side.
SOFTGRAIN ?= build/softgrain
SCALE ?= default
OUT ?= figures
# MPIRUN="mpirun -n 64" (or "srun"): the launcher of the ensemble figures' runs (reproductions/README.md, "Ensemble figures under MPI").
MPIRUN ?=
FIGURES := $(shell python3 scripts/reproduce list)
REPORTS := $(FIGURES:%=$(OUT)/%.claims.json)

.PHONY: all FORCE
all: $(OUT)/index.html

$(OUT)/index.html: $(REPORTS)
	@python3 scripts/reproduce index --out $(OUT)

# Runs shared between figures (the same scene, parameters and binary, e.g. SPD Figs. 27-29) are made once per
# invocation: the directory is emptied when make reads this file, so no run of an earlier invocation (whose
# timings belong to another moment) is reused.
RUNS := $(OUT)/runs-$(SCALE)
$(shell rm -rf $(RUNS))

# Progress: one line per finished figure, with its elapsed time, its expected time (its wall time in the
# previous run at this scale, read here from the report that run left in $(OUT), before any figure replaces
# it) and the figures done of those this invocation makes (every figure, or the reports named as goals, e.g.
# `make -f scripts/figures.mk OUT=... $(OUT)/spd/spd-fig7.claims.json`) with an estimate of the time left.
PROGRESS := $(OUT)/progress-$(SCALE)
PLANNED := $(patsubst $(OUT)/%.claims.json,%,$(filter %.claims.json,$(MAKECMDGOALS)))
$(shell python3 scripts/reproduce start-progress $(PROGRESS) $(or $(PLANNED),$(FIGURES)) --out $(OUT) --scale $(SCALE))

# A figure that fails writes its error into its report and exits 1; make goes on with the others (the '-'),
# and the index, written last, shows the failed figures at the top and exits 1 naming them.
$(OUT)/%.claims.json: FORCE
	-@python3 scripts/reproduce figure $* --scale $(SCALE) --softgrain $(SOFTGRAIN) --out $(OUT) --runs $(RUNS) \
	  --progress $(PROGRESS) $(if $(MPIRUN),--mpirun "$(MPIRUN)")
