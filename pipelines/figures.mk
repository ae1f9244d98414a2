# The paper's figures (Sec. 8) from assets/scenes/, included by Makefile:
#   make -C pipelines figures QUALITY=preview   every scene at its "preview" preset (minutes on 2 cores)
#   make -C pipelines figures QUALITY=final     the paper's resolution (hours)
# Writes under $(FIGURES) = $(OUT)/figures/$(QUALITY): per scene SCENE/frames (simulation), SCENE/meshes,
# SCENE/images/beauty.NNNN.{exr,png} of the chosen frames, SCENE/contact_sheet.png, SCENE/water.png and
# SCENE/transfers.png (the manifest's water ledger); fig3_single_particle.png, fig4_contact_angles.png and
# table1.md at the top. Meshing and rendering are one target per frame (make -j parallelises them);
# each scene simulates once. Everything is incremental: a second run does nothing.
QUALITY ?= preview
ifeq ($(filter $(QUALITY),preview final),)
$(error QUALITY must be preview or final, found '$(QUALITY)')
endif
FIGURES ?= $(OUT)/figures/$(QUALITY)
SCENES_DIR := $(ROOT)/assets/scenes
FIGURE_SCENES ?= drop_notex drop sca_logo_tex sca_logo glass contact_angles
TABLE1_SCENES ?= drop_notex drop sca_logo_tex sca_logo glass
PRESET_ARG := $(if $(filter preview,$(QUALITY)),--preset preview)
PYTHON ?= python3
# Several tools at once (make -j) on few cores: OpenMP threads must sleep, not spin, while they wait.
OMP_WAIT_POLICY ?= PASSIVE
export OMP_WAIT_POLICY
# Quiet tools; make prints the commands.
TOOL_FLAGS ?= --quiet
# Table 1's timing runs are benchmarks. flock keeps them from overlapping one another, and each runs with
# libgomp's default wait policy (spin, then sleep), as a simulation alone on its cores should: PASSIVE costs a
# 64^3 air step 20-25 ms on 2 cores (docs/benchmarks.md, "OpenMP's wait policy is the scenes' Grid gap").
# Timings taken while make -j runs other tools beside them measure the machine's load, not the simulator.
TIMING_WAIT_POLICY ?= default
TIMING_ENV := $(if $(filter default,$(TIMING_WAIT_POLICY)),env -u OMP_WAIT_POLICY,env OMP_WAIT_POLICY=$(TIMING_WAIT_POLICY))

# Chosen frames per scene and quality (frame = time x frame_rate_hz of the scene or its preset).
FRAMES_preview_drop_notex    := 0 4 8
FRAMES_preview_drop          := 0 4 8
FRAMES_preview_sca_logo_tex  := 0 3 6
FRAMES_preview_sca_logo      := 0 3 6
FRAMES_preview_glass         := 0 2
FRAMES_preview_contact_angles := 0
FRAMES_final_drop_notex      := 0 24 48 72
FRAMES_final_drop            := 0 24 48 72
FRAMES_final_sca_logo_tex    := 0 32 64 96
FRAMES_final_sca_logo        := 0 32 64 96
FRAMES_final_glass           := 0 24 48
FRAMES_final_contact_angles  := 0
# The drop frame of paper Fig. 4 (meshed with and without the corrections of Sec. 7).
FIG4_FRAME_preview := 4
FIG4_FRAME_final   := 24

frames_of = $(FRAMES_$(QUALITY)_$(1))
pad4 = $(shell printf %04d $(1))
# Inputs of a scene's simulation besides the file: the meshes and images it names.
assets_of = $(shell $(PYTHON) $(ROOT)/pipelines/figure_data.py assets $(SCENES_DIR)/$(1).json)

.PHONY: figure-files figures-clean
.DELETE_ON_ERROR:

# simulate: one target per scene; the stamp is written only after success.
define scene_rules
$(FIGURES)/$(1)/simulated.stamp: $(SCENES_DIR)/$(1).json $(call assets_of,$(1)) $(SIMULATE)
	@mkdir -p $(FIGURES)/$(1)
	$(SIMULATE) $(SCENES_DIR)/$(1).json -o $(FIGURES)/$(1) $(PRESET_ARG) $(TOOL_FLAGS) > $(FIGURES)/$(1)/simulate.log
	@touch $$@

$(FIGURES)/$(1)/ledger.dat: $(FIGURES)/$(1)/simulated.stamp $(ROOT)/pipelines/figure_data.py
	$(PYTHON) $(ROOT)/pipelines/figure_data.py ledger $(FIGURES)/$(1)/frames > $$@

$(FIGURES)/$(1)/water.png: $(FIGURES)/$(1)/ledger.dat $(ROOT)/pipelines/plot-ledger.gp
	gnuplot -e "data='$$<'; scene='$(1)'; water='$$@'; transfers='$(FIGURES)/$(1)/transfers.png'" $(ROOT)/pipelines/plot-ledger.gp

# The renderer writes beauty.NNNN.png with the EXR: rules name the EXR, recipes read the PNG.
$(FIGURES)/$(1)/contact_sheet.png: $(foreach f,$(call frames_of,$(1)),$(FIGURES)/$(1)/images/beauty.$(call pad4,$(f)).exr)
	oiiotool $$(^:.exr=.png) --mosaic:pad=4 $(words $(call frames_of,$(1)))x1 -o $$@

# water.png's recipe writes transfers.png too.
FIGURE_FILES += $(FIGURES)/$(1)/contact_sheet.png $(FIGURES)/$(1)/water.png
$(foreach f,$(call frames_of,$(1)),$(eval $(call frame_rules,$(1),$(call pad4,$(f)),$(f),meshes,images,)))
endef

# mesh and render: one target per frame. $(6): extra mesher flags (--no-correction).
define frame_rules
$(FIGURES)/$(1)/$(4)/liquid.$(2).ply: $(FIGURES)/$(1)/simulated.stamp $(MESH)
	$(MESH) $(FIGURES)/$(1)/frames -o $(FIGURES)/$(1)/$(4) --frames $(3) $(6) $(TOOL_FLAGS)

$(FIGURES)/$(1)/$(5)/beauty.$(2).exr: $(FIGURES)/$(1)/$(4)/liquid.$(2).ply $(SCENES_DIR)/$(1).json $(RENDER)
	$(RENDER) $(SCENES_DIR)/$(1).json --frames-dir $(FIGURES)/$(1)/frames --meshes-dir $(FIGURES)/$(1)/$(4) -o $(FIGURES)/$(1)/$(5) --frames $(3) $(TOOL_FLAGS)
endef

# Table 1: the paper-resolution scenes timed for a few steps (even in preview) through their
# "table1" preset; QUALITY=final times the whole final run instead.
define timing_rules
ifeq ($(QUALITY),final)
TIMING_DIR_$(1) := $(FIGURES)/$(1)
$(FIGURES)/timing/$(1).stamp: $(FIGURES)/$(1)/simulated.stamp
	@mkdir -p $(FIGURES)/timing && touch $$@
else
TIMING_DIR_$(1) := $(FIGURES)/timing/$(1)
$(FIGURES)/timing/$(1).stamp: $(SCENES_DIR)/$(1).json $(call assets_of,$(1)) $(SIMULATE)
	@mkdir -p $(FIGURES)/timing/$(1)
	flock $(FIGURES)/timing/.lock $(TIMING_ENV) $(SIMULATE) $(SCENES_DIR)/$(1).json -o $(FIGURES)/timing/$(1) --preset table1 $(TOOL_FLAGS) > $(FIGURES)/timing/$(1)/simulate.log
	@touch $$@
endif
endef

$(foreach s,$(FIGURE_SCENES),$(eval $(call scene_rules,$(s))))
$(foreach s,$(TABLE1_SCENES),$(eval $(call timing_rules,$(s))))

# Paper Fig. 3: the single-particle drops plain (Eq. 19) and corrected (Eq. 20-24), one above the other.
$(eval $(call frame_rules,contact_angles,0000,0,meshes_uncorrected,images_uncorrected,--no-correction))
$(FIGURES)/fig3_single_particle.png: $(FIGURES)/contact_angles/images_uncorrected/beauty.0000.exr $(FIGURES)/contact_angles/images/beauty.0000.exr
	oiiotool $(^:.exr=.png) --mosaic:pad=4 1x2 -o $@

# Paper Fig. 4: a drop frame meshed without (left) and with (right) the corrections.
FIG4 := $(call pad4,$(FIG4_FRAME_$(QUALITY)))
$(eval $(call frame_rules,drop,$(FIG4),$(FIG4_FRAME_$(QUALITY)),meshes_uncorrected,images_uncorrected,--no-correction))
$(FIGURES)/fig4_contact_angles.png: $(FIGURES)/drop/images_uncorrected/beauty.$(FIG4).exr $(FIGURES)/drop/images/beauty.$(FIG4).exr
	oiiotool $(^:.exr=.png) --mosaic:pad=4 2x1 -o $@

$(FIGURES)/table1.md: $(foreach s,$(TABLE1_SCENES),$(FIGURES)/timing/$(s).stamp) $(ROOT)/pipelines/figure_data.py
	TABLE1_NOTE="$(if $(filter final,$(QUALITY)),Timed over the whole final run.,Timed over the first steps of each scene (its table1 preset) while the figures themselves ran at preview quality; the per-step time is what Table 1 compares.) OpenMP wait policy: $(if $(filter final,$(QUALITY)),$(OMP_WAIT_POLICY),$(TIMING_WAIT_POLICY))." \
	$(PYTHON) $(ROOT)/pipelines/figure_data.py table1 $@ $(foreach s,$(TABLE1_SCENES),$(s)=$(TIMING_DIR_$(s)))

FIGURE_FILES += $(FIGURES)/fig3_single_particle.png $(FIGURES)/fig4_contact_angles.png $(FIGURES)/table1.md
# A subset (FIGURE_SCENES=...) leaves out the figures that need scenes it lacks.
ifeq ($(filter contact_angles,$(FIGURE_SCENES)),)
FIGURE_FILES := $(filter-out %/fig3_single_particle.png,$(FIGURE_FILES))
endif
ifeq ($(filter drop,$(FIGURE_SCENES)),)
FIGURE_FILES := $(filter-out %/fig4_contact_angles.png,$(FIGURE_FILES))
endif
ifeq ($(TABLE1_SCENES),)
FIGURE_FILES := $(filter-out %/table1.md,$(FIGURE_FILES))
endif

figure-files: $(FIGURE_FILES)
	@echo "figures ($(QUALITY)): $(FIGURES)"

figures-clean:
	rm -rf $(FIGURES)
