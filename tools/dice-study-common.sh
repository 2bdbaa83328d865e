# What the dice studies (tools/dice-study.sh, tools/dice-tower-study.sh) share: sourced, not run.
# dice_study_setup NAME THROWS sets tumble (TUMBLE, the built CLI), throws (THROWS, default
# THROWS), seed (SEED, default 1) and out_dir (OUT_DIR, default docs/images), makes the scratch
# folder work (removed on exit), and stops when tumble has not been built.
dice_study_setup() {
    tumble="${TUMBLE:-build/apps/cli/tumble}"
    throws="${THROWS:-$2}"
    seed="${SEED:-1}"
    out_dir="${OUT_DIR:-docs/images}"
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
    if [[ ! -x "$tumble" ]]; then
        echo "$1: $tumble not found; build first (cmake --build build)" >&2
        exit 1
    fi
}
