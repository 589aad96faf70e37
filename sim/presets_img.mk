# Before/after image of every preset this build carries, on a real photo
# (sim/docs/presets/make_images.sh). Included by the top Makefile.
#   make preset-images   sim/docs/presets/<name>.png: input | fixed | float | diff
.PHONY: preset-images

preset-images: sim
	@sh sim/docs/presets/make_images.sh $(B)
