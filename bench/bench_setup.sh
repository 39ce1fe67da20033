# Set-up shared by the bench scripts (sourced, not run): build what a bench runs, and install the
# Debian packages it needs when they are missing (never added to .ci).
#   bench_build ROOT BUILD PROGRAM...   configures BUILD (Release, warnings as errors) and builds
#                                       the programs (paths under BUILD: apps/inpact,
#                                       bench/solver_floor) that are not there yet
#   bench_need_python MODULE...         needs python3-MODULE for /usr/bin/python3 (Debian's)
#   bench_need PACKAGE                  needs a Debian package (the caller tests for it)
#   bench_install_needed                apt-get installs what was needed (as root or through sudo)

bench_build() {
  local root=$1 build=$2
  shift 2
  local targets=() program
  for program in "$@"; do [ -x "$build/$program" ] || targets+=("$(basename "$program")"); done
  [ ${#targets[@]} -gt 0 ] || return 0
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DINPACT_WARNINGS_AS_ERRORS=ON >/dev/null
  cmake --build "$build" --target "${targets[@]}" -j 2
}

bench_needed=()
bench_need_python() {
  local module
  for module in "$@"; do
    /usr/bin/python3 -c "import $module" 2>/dev/null || bench_needed+=("python3-$module")
  done
}
bench_need() { bench_needed+=("$@"); }
bench_install_needed() {
  [ ${#bench_needed[@]} -gt 0 ] || return 0
  local sudo_cmd=""
  [ "$(id -u)" = 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get install -y "${bench_needed[@]}" >/dev/null
}
