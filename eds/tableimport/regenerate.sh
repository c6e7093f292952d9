#!/usr/bin/env bash
# Rebuild the vendor EDS files and their import reports from the manuals in ../shared/seeds.
# Run from the project root: bash eds/tableimport/regenerate.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
SEEDS=../shared/seeds
run() {  # name, manuals...
    local name=$1
    shift
    python -m cantools_od import-table "$@" --overrides "eds/tableimport/$name.overrides.toml" \
        --report "eds/tableimport/$name.report.md" -o "eds/tableimport/$name.eds" -q
}
run elmo_simpliq "$SEEDS/000_3cb15f7fa7effd3d.txt" "$SEEDS/001_6a6bb34a259a2c0a.txt"
run sanyo_sanmotion_r "$SEEDS/002_ceb85346843789e0.txt"
run moons_canopen "$SEEDS/003_07695d6ad21280c4.txt"
run nidec_si_canopen "$SEEDS/004_154176570a080d38.txt"
