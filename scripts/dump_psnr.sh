#!/bin/sh
# PSNR over covered pixels of two --dump CSVs (same pixels, same order): r,g,b are columns 7-9.
paste -d, "$1" "$2" | awk -F, -v n="$(head -1 "$1" | tr ',' '\n' | wc -l)" 'NR>1{for(k=7;k<=9;k++){d=$k-$(k+n); se+=d*d; c++}} END{printf "%.2f dB over %d pixels\n", 10*log(255*255*c/se)/log(10), c/3}'
