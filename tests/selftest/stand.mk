# Stand-in checks for the runner's self-test: the same recipe shapes the
# real checks use (tests/runbin.sh around a binary, a make target whose
# recipe is its own check, a whole-check skip). SB is the stand-in dir.
.PHONY: chk-good chk-segv chk-exit chk-compile chk-fail-compile chk-skip
chk-good:
	@sh tests/runbin.sh "good:" -- $(SB)/good
chk-segv:
	@sh tests/runbin.sh "piped crash:" "passed" -- $(SB)/segv
chk-exit:
	@sh tests/runbin.sh "canary:" -- $(SB)/canary; a=$$?; \
	sh tests/runbin.sh "good:" -- $(SB)/good && exit $$a
chk-compile:
	@true
chk-fail-compile:
	@false
chk-skip:
	@echo "skipped: chk-skip: its tool is not installed"
