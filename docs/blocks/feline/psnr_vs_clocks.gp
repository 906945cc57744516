set terminal pngcairo size 900,600
set output 'docs/blocks/feline/psnr_vs_clocks.png'
set title "<default scene>: PSNR vs clocks per pixel"
set xlabel 'clocks per pixel (RTL cycle model; Feline: N tu\_trilinear passes)'
set ylabel 'PSNR vs box truth (dB)'
set logscale x
set grid
set key off
plot 'docs/blocks/feline/psnr_vs_clocks.dat' using 2:3 with points pt 7 ps 1.5, '' using 2:3:1 with labels offset 0,1 font ',9'
