# Included by `make reproduce-figures`: one target per figure, so that make -j runs figures side by side.
SOFTGRAIN ?= build/softgrain
SCALE ?= default
OUT ?= figures
FIGURES := $(shell python3 scripts/reproduce list)
REPORTS := $(FIGURES:%=$(OUT)/%.claims.json)

.PHONY: all FORCE
all: $(OUT)/index.html

$(OUT)/index.html: $(REPORTS)
	@python3 scripts/reproduce index --out $(OUT)

$(OUT)/%.claims.json: FORCE
	@python3 scripts/reproduce figure $* --scale $(SCALE) --softgrain $(SOFTGRAIN) --out $(OUT)
