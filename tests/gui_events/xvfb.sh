#!/bin/sh
# Runs a command on its own virtual X screen, 1920×1080 unless CG_SCREEN says otherwise
# (e.g. CG_SCREEN=1280x720): the GUI event tests open the real viewer window there.
exec xvfb-run -a -s "-screen 0 ${CG_SCREEN:-1920x1080}x24" "$@"
