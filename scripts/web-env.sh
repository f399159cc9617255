# Sourced by the browser build's scripts: Debian's emscripten runs its JS tools with the `node`
# in PATH (NODE_JS in /usr/share/emscripten/.emscripten), which may be a Node from elsewhere
# (NodeSource's here) that does not see Debian's node-acorn: point it at Debian's modules.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}

# CG_BUILD_LOCK=FILE: the scripts compile while holding that lock (flock), on a machine shared
# with others: "${build_lock[@]}" before a build command.
build_lock=()
if [[ -n ${CG_BUILD_LOCK:-} ]]; then build_lock=(flock "$CG_BUILD_LOCK"); fi
