#!/usr/bin/env bash
# bdtCuda.sh with the second bond law: the BDT granite case with `bond { model brittleBPM; }`
# on the CUDA backend against the CPU backend (needs a GPU; exit 77 = skipped otherwise).
BOND_LAW=brittleBPM exec bash "$(dirname "$0")/bdtCuda.sh" "$@"
