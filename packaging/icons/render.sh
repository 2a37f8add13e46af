#!/usr/bin/env bash
# Renders the hicolor PNG sizes from the SVG (rsvg-convert, Debian librsvg2-bin).
# The PNGs are committed, so building the package does not need librsvg2-bin;
# run this after changing the SVG.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
for size in 16 24 32 48 64 128 256; do
    rsvg-convert -w "$size" -h "$size" org.driftlab.DriftLab.svg -o "org.driftlab.DriftLab-$size.png"
done
