# Front door. On a fresh Debian 12 machine `make figures` and `make test` are
# each enough: they install what is missing (scripts/install-deps.sh, once per
# change of that script), configure, build and run.
#
#   make deps                     install the Debian packages for build, test and figures
#   make build                    configure (Release) and build into build/
#   make test                     build, then ctest (unit, regression, stability, figures)
#   make figures                  run every experiment's paper scene, render figures/out/* (only what changed)
#   make scaling                  strong scaling under MPI and the cluster projection (bench/mpi_scaling.py)
#   make paper                    figures + scaling + tables and overview figures from summary.json + paper/main.pdf
#   make experiment NAME=x [SCENE=v] ARGS='--study S --set key=value'   one experiment (+ the figures of what ran)
#   make bench                    throughput benchmarks (Google Benchmark)
#   make plan-rates               measure --plan's rates on the paper scenes' runs, rewrite experiments/plan_rates.toml
#   make new-study EXPERIMENT=x STUDY=s PAPER=006 ITEM='Fig. 3' [SYSTEM=y]   the skeleton of a new experiment
#                                 (tools/new_study: README "Adding a figure")
#   make methods-gpi              rewrite figures/methods.gpi from the method registry (after changing it)
#   make clean                    remove build/, results/, figures/out/, paper outputs

BUILD     ?= build
RESULTS   ?= results
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_ARGS ?=
# The interpreter of scripts/overview_figures.py: Debian's, with python3-matplotlib (the PATH python3 may lack it).
MPL_PYTHON ?= /usr/bin/python3
EXPERIMENTS := $(sort $(notdir $(patsubst %/,%,$(dir $(wildcard experiments/*/*.cpp)))))
DEPS_STAMP := .deps
UNCHECKED := figures/out/.unchecked   # figures rendered by make figures whose text is not yet checked
RENDERED := figures/out/.rendered     # figures rendered so far by this make figures (its progress lines)

.PHONY: all deps build build-figures test figures figure-runs figure-files scaling paper overview-figures experiment bench plan-rates methods-gpi new-study clean FORCE
all: build

$(DEPS_STAMP)/%.stamp: scripts/install-deps.sh
	scripts/install-deps.sh $*
	@mkdir -p $(DEPS_STAMP) && touch $@

deps: $(DEPS_STAMP)/figures.stamp

$(BUILD)/CMakeCache.txt: | $(DEPS_STAMP)/build.stamp
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

# (scripts/build_progress.py adds the time so far and an estimate of the time left to CMake's percentages)
build: $(DEPS_STAMP)/build.stamp $(BUILD)/CMakeCache.txt
	@scripts/build_progress.py cmake --build $(BUILD) -j $(JOBS)

# What the runs and figures need: the experiments and geomint-methods (CMake target geomint_figures), no test
# suite or benchmark.
build-figures: $(DEPS_STAMP)/build.stamp $(BUILD)/CMakeCache.txt
	@scripts/build_progress.py cmake --build $(BUILD) -j $(JOBS) --target geomint_figures

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# Paper scenes: experiments/<name>/<name>.toml, results in $(RESULTS)/<name>, figures
# figures/<name>_*.gp; a second scene experiments/<name>/<variant>.toml (not quick*)
# has the id <name>-<variant> for its results and figures.
scene_id = $(if $(filter $(1),$(2)),$(1),$(1)-$(2))

# One experiment with its paper scene (or SCENE=<variant>), then its figures. With ARGS (a reviewer's
# --set or --study) the run goes to $(RESULTS)/<id>+<8 hex digits of a hash of ARGS>, or to OUT=DIR, and its
# figures into that directory's figures/: never over the paper run that make figures and make paper report.
SCENE ?= $(NAME)
ARGS_QUOTED = '$(subst ','\'',$(ARGS))'
experiment: build-figures $(DEPS_STAMP)/figures.stamp
	@test -n "$(NAME)" || { echo "usage: make experiment NAME=<one of: $(EXPERIMENTS)> [SCENE=<variant>] [ARGS='--study S --set key=value'] [OUT=DIR]"; exit 2; }
	@id=$(call scene_id,$(NAME),$(SCENE)); out="$(OUT)"; figs=figures/out; \
	if [ -z "$$out" ] && [ -n "$(strip $(ARGS))" ]; then \
	  out=$(RESULTS)/$$id+$$(printf '%s' $(ARGS_QUOTED) | sha256sum | cut -c1-8); fi; \
	if [ -n "$$out" ]; then figs=$$out/figures; else out=$(RESULTS)/$$id; fi; \
	echo "== $$out"; \
	$(BUILD)/bin/$(NAME) --scene experiments/$(NAME)/$(SCENE).toml --out "$$out" $(ARGS) && \
	tests/figures/render_figures.sh --only-available "$$out" "$$figs" $(wildcard figures/$(call scene_id,$(NAME),$(SCENE))_*.gp)

# Every paper scene experiments/<name>/<scene>.toml (not quick*, not published.toml) has the id
# <name> or <name>-<scene>. Its results are remade when the binary, a scene file of the experiment
# (the scene, its bases) or its published.toml is newer than results/<id>/run.json (written last,
# after the CSVs); each figure when its script, figures/common.gp or the run is newer than it.
# A cluster scene (a line "# scale: cluster", e.g. experiments/energy_map/fine.toml) is not a paper
# scene: it is run with mpirun (README: Running on a cluster), not by make figures.
CLUSTER_SCENES := $(shell grep -l '^\# scale: cluster' experiments/*/*.toml)
PAPER_SCENES := $(filter-out %/published.toml $(CLUSTER_SCENES),$(foreach n,$(EXPERIMENTS),$(filter-out experiments/$(n)/quick%,$(wildcard experiments/$(n)/*.toml))))
id_of = $(call scene_id,$(word 2,$(subst /, ,$(1))),$(basename $(notdir $(1))))
define SCENE_RULES
$(RESULTS)/$(3)/run.json: $(BUILD)/bin/$(1) $(2) $(filter-out experiments/$(1)/quick% $(CLUSTER_SCENES),$(wildcard experiments/$(1)/*.toml)) $(if $(filter $(3),$(STALE_RUNS)),FORCE)
	@echo "== $(3)"
	@start=$$$$(date +%s%N); $(BUILD)/bin/$(1) --scene $(2) --out $(RESULTS)/$(3) $$(if $$(TIMING_CONCURRENCY),--timing-concurrency $$(TIMING_CONCURRENCY)) && \
	  awk -v ns=$$$$(( $$$$(date +%s%N) - start )) 'BEGIN { printf "== $(3): %.1f s\n", ns / 1e9 }'
FIGURES_$(3) := $(patsubst figures/%.gp,figures/out/%.pdf,$(wildcard figures/$(3)_*.gp))
$$(FIGURES_$(3)): figures/out/%.pdf: figures/%.gp figures/common.gp $(wildcard figures/*.gpi) $(RESULTS)/$(3)/run.json
	@tests/figures/render_figures.sh --check-later $(UNCHECKED) $(RESULTS)/$(3) figures/out $$<
ALL_FIGURES += $$(FIGURES_$(3)) $(RESULTS)/$(3)/run.json
ALL_RUNS += $(RESULTS)/$(3)/run.json
endef
# A results directory that is not its paper scene's run (another scene, --set overrides, not every
# study: scripts/paper_runs.py) is rerun, whatever its timestamps say.
STALE_RUNS := $(shell python3 scripts/paper_runs.py stale $(RESULTS) $(foreach sc,$(PAPER_SCENES),$(call id_of,$(sc))=$(sc)))
$(foreach sc,$(PAPER_SCENES),$(eval $(call SCENE_RULES,$(word 2,$(subst /, ,$(sc))),$(sc),$(call id_of,$(sc)))))
FORCE:
$(BUILD)/bin/%: ;   # made by `build`, before figure-files is asked for

# The runs one after another (each uses every core, and times itself; whether the cores time alike is measured
# by the first run that times and read by the others: --timing-concurrency, a file of this make), then the figures
# rendered in parallel; at the end each experiment's wall time (its run.json), the rendering's and that of the
# whole make figures.
figures: build-figures $(DEPS_STAMP)/figures.stamp
	@start=$$(date +%s.%N); shared=$(BUILD)/timing_concurrency_of_make_figures.$$$$; trap 'rm -f $$shared' EXIT; \
	  $(MAKE) --no-print-directory figure-runs TIMING_CONCURRENCY=$$shared && render=$$(date +%s.%N) && \
	  n=$$($(MAKE) --no-print-directory -n figure-files | grep -c 'render_figures.sh' || true) && \
	  { [ $$n = 0 ] || echo "== rendering $$n figures"; } && mkdir -p figures/out && : > $(RENDERED) && \
	  GEOMINT_RENDER_PROGRESS="$$n $$(date +%s.%N) $(RENDERED)" $(MAKE) --no-print-directory -j $(JOBS) figure-files && \
	  python3 scripts/figure_times.py --rendering-from $$render $(RESULTS) $$start $(foreach sc,$(PAPER_SCENES),$(call id_of,$(sc)))

figure-runs: $(ALL_RUNS)

# Each figure rendered by its rule; the text of all of them checked at the end, 20 to a process (a figure
# that fails is removed, so that the next make renders it again; a list left by an interrupted make is
# checked by the next).
figure-files: $(ALL_FIGURES)
	@if [ -s $(UNCHECKED) ]; then \
	  sort -u $(UNCHECKED) | xargs -n 20 -P $(JOBS) python3 tests/figures/check_figure_text.py --remove-failing; \
	  rc=$$?; rm -f $(UNCHECKED); [ $$rc = 0 ] || exit 1; fi

# The report: the generated parts from the runs and from a run of the hard-case tests, with the quick runs they wait on (scripts/report.py
# computes nothing), LaTeX, then a check of the PDF's text (no undefined reference, missing value, NaN; the contents and ledger in front).
# Strong scaling of the energy map under MPI and the projection of the cluster scene (the cost chapter).
$(RESULTS)/mpi_scaling/summary.json: $(BUILD)/bin/energy_map bench/mpi_scaling.py experiments/energy_map/energy_map.toml experiments/energy_map/fine.toml
	python3 bench/mpi_scaling.py $(BUILD) $(RESULTS)/mpi_scaling
scaling: build-figures
	@$(MAKE) --no-print-directory $(RESULTS)/mpi_scaling/summary.json

# The hard cases are rerun only when a binary or the test list changed (a second make paper with
# nothing changed runs no test).
paper/generated/hardcases.xml: $(wildcard $(BUILD)/bin/*) $(wildcard $(BUILD)/tests/CTestTestfile.cmake)
	@mkdir -p paper/generated
	ctest --test-dir $(BUILD) -j $(JOBS) -L hardcase --output-junit $(CURDIR)/$@ > /dev/null

paper: figures scaling build $(DEPS_STAMP)/paper.stamp paper/generated/hardcases.xml
	@mkdir -p paper/generated
	$(BUILD)/bin/geomint-methods --json > paper/generated/methods.json
	ctest --test-dir $(BUILD) --show-only=json-v1 > paper/generated/tests.json
	python3 scripts/report.py $(RESULTS) paper/generated --methods paper/generated/methods.json \
	  --papers paper/papers.toml --tests paper/generated/tests.json --quick $(BUILD)/test-results \
	  --junit paper/generated/hardcases.xml --paper-scenes $(foreach sc,$(PAPER_SCENES),$(call id_of,$(sc))=$(sc))
	@$(MAKE) --no-print-directory overview-figures
	cd paper && latexmk -pdf -interaction=nonstopmode -halt-on-error main.tex
	python3 scripts/check_pdf.py paper/main.pdf --log paper/main.log --tex paper/sections/*.tex paper/sections/cost/*.tex paper/generated/*.tex

# The report's two overview figures (scripts/overview_figures.py, matplotlib: about 3 s, so not part of make
# figures), from the paper runs and the method registry. A make of its own, called by make paper after the runs, so
# that their new times are seen; remade when a run, the registry or the scripts changed.
OVERVIEW := paper/generated/overview-comparisons.pdf paper/generated/overview-cost.pdf
overview-figures: $(OVERVIEW)
$(OVERVIEW) &: $(wildcard $(RESULTS)/*/summary.json) $(BUILD)/bin/geomint-methods scripts/overview_figures.py \
               scripts/report.py scripts/report_tables.py scripts/tex_format.py scripts/paper_runs.py
	$(MPL_PYTHON) scripts/overview_figures.py $(RESULTS) paper/generated --methods paper/generated/methods.json \
	  --paper-scenes $(foreach sc,$(PAPER_SCENES),$(call id_of,$(sc))=$(sc))

bench: $(DEPS_STAMP)/build.stamp $(DEPS_STAMP)/figures.stamp $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target geomint_bench geomint_energy_map_bench
	$(BUILD)/bin/geomint_bench
	bench/run_energy_map_bench.sh $(BUILD)

plan-rates: figure-runs
	python3 scripts/plan_rates.py $(RESULTS) $(BUILD)

new-study:
	@test -n "$(EXPERIMENT)" -a -n "$(STUDY)" -a -n "$(PAPER)" -a -n "$(ITEM)" || { echo "usage: make new-study EXPERIMENT=<name> STUDY=<study> PAPER=<id> ITEM='<item>' [SYSTEM=<system>]"; exit 2; }
	tools/new_study '$(EXPERIMENT)' '$(STUDY)' --paper '$(PAPER)' --item '$(ITEM)' $(if $(SYSTEM),--system '$(SYSTEM)')

methods-gpi: $(DEPS_STAMP)/build.stamp $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target geomint-methods
	$(BUILD)/bin/geomint-methods --gnuplot > figures/methods.gpi

clean:
	rm -rf $(BUILD) $(RESULTS) figures/out paper/generated
	-cd paper && latexmk -C main.tex >/dev/null 2>&1
