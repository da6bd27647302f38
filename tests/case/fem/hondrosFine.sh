#!/usr/bin/env bash
# The Hondros check on a finer 1.25 mm mesh (label validation, a few minutes on 2 cores).
exec bash "$(dirname "$0")/hondros.sh" "$1" 1.25e-3 0.07
