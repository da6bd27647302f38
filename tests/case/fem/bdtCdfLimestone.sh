#!/usr/bin/env bash
# BDT limestone FEM failure-load CDF against Table 5 over 10 seeds (validation; bdtCdf.sh).
exec bash "$(dirname "$0")/bdtCdf.sh" "$1" limestone 10
