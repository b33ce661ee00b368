# Front door. On a fresh Debian 12 machine `make figures` and `make test` are
# each enough: they install what is missing (scripts/install-deps.sh, once per
# change of that script), configure, build and run.
#
#   make deps                     install the Debian packages for build, test and figures
#   make build                    configure (Release) and build into build/
#   make test                     build, then ctest (unit, regression, stability, figures)
#   make figures                  run every experiment's paper scene, render figures/out/*
#   make paper                    figures + tables from summary.json + paper/main.pdf
#   make experiment NAME=x [SCENE=v] ARGS='--study S --set key=value'   one experiment (+ the figures of what ran)
#   make bench                    throughput benchmarks (Google Benchmark)
#   make clean                    remove build/, results/, figures/out/, paper outputs

BUILD     ?= build
RESULTS   ?= results
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_ARGS ?=
EXPERIMENTS := $(notdir $(patsubst %/,%,$(dir $(wildcard experiments/*/main.cpp))))
DEPS_STAMP := .deps

.PHONY: all deps build test figures paper experiment bench clean
all: build

$(DEPS_STAMP)/%.stamp: scripts/install-deps.sh
	scripts/install-deps.sh $*
	@mkdir -p $(DEPS_STAMP) && touch $@

deps: $(DEPS_STAMP)/figures.stamp

$(BUILD)/CMakeCache.txt: | $(DEPS_STAMP)/build.stamp
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

build: $(DEPS_STAMP)/build.stamp $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# Paper scenes: experiments/<name>/<name>.toml, results in $(RESULTS)/<name>, figures
# figures/<name>_*.gp; a second scene experiments/<name>/<variant>.toml (not quick*)
# has the id <name>-<variant> for its results and figures.
scene_id = $(if $(filter $(1),$(2)),$(1),$(1)-$(2))

# One experiment with its paper scene (or SCENE=<variant>, or ARGS), then its figures.
SCENE ?= $(NAME)
experiment: build $(DEPS_STAMP)/figures.stamp
	@test -n "$(NAME)" || { echo "usage: make experiment NAME=<one of: $(EXPERIMENTS)> [SCENE=<variant>] [ARGS='--study S --set key=value']"; exit 2; }
	$(BUILD)/bin/$(NAME) --scene experiments/$(NAME)/$(SCENE).toml --out $(RESULTS)/$(call scene_id,$(NAME),$(SCENE)) $(ARGS)
	tests/figures/render_figures.sh --only-available $(RESULTS)/$(call scene_id,$(NAME),$(SCENE)) figures/out $(wildcard figures/$(call scene_id,$(NAME),$(SCENE))_*.gp)

figures: build $(DEPS_STAMP)/figures.stamp
	@for name in $(EXPERIMENTS); do \
	  for scene in experiments/$$name/*.toml; do \
	    base=$$(basename $$scene .toml); \
	    case $$base in quick*) continue ;; esac; \
	    id=$$name; [ "$$base" = "$$name" ] || id=$$name-$$base; \
	    echo "== $$id"; \
	    $(BUILD)/bin/$$name --scene $$scene --out $(RESULTS)/$$id || exit 1; \
	    tests/figures/render_figures.sh $(RESULTS)/$$id figures/out $$(ls figures/$${id}_*.gp 2>/dev/null) || exit 1; \
	  done; \
	done

paper: figures $(DEPS_STAMP)/paper.stamp
	python3 scripts/paper_tables.py $(RESULTS) paper/generated
	cd paper && latexmk -pdf -interaction=nonstopmode -halt-on-error main.tex

bench: $(DEPS_STAMP)/build.stamp $(DEPS_STAMP)/figures.stamp $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target geomint_bench geomint_energy_map_bench
	$(BUILD)/bin/geomint_bench
	bench/run_energy_map_bench.sh $(BUILD)

clean:
	rm -rf $(BUILD) $(RESULTS) figures/out paper/generated
	-cd paper && latexmk -C main.tex >/dev/null 2>&1
