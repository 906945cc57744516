set terminal pngcairo size 1500,480 noenhanced
set grid
set key top left font ',8'
set ylabel 'PSNR dB (vs 256-layer exact march)'
angles = '45 60 80 85'
maps = 'smooth bricks noisy'
set output '/tmp/relief_h3_plots/relief_psnr_vs_steps.png'
set xlabel 'march steps (iterations) per pixel'
set multiplot layout 1,3
do for [m=1:3] {
  set title word(maps, m)
  plot for [a=1:4] '/tmp/relief_h3_plots/relief_quality.dat' index ((m-1)*4+a-1) every ::0::4 using 2:4 with linespoints lc a pt 7 title 'N=4..32 '.word(angles, a).' deg', \
       for [a=1:4] '' index ((m-1)*4+a-1) every ::5::5 using 2:4 with points lc a pt 9 ps 2 title (a == 1 ? 'adaptive' : ''), \
       for [a=1:4] '' index ((m-1)*4+a-1) every ::6::6 using 2:4 with points lc a pt 4 ps 1.5 title (a == 1 ? 'iter-seed' : ''), \
       for [a=1:4] '' index ((m-1)*4+a-1) every ::7::7 using 2:4 with points lc a pt 12 ps 1.5 title (a == 1 ? 'iter-norm' : '')
}
unset multiplot
set output '/tmp/relief_h3_plots/relief_psnr_vs_cycles.png'
set xlabel 'cycles per pixel (POM k + 1, iterative k + 3)'
set multiplot layout 1,3
do for [m=1:3] {
  set title word(maps, m)
  plot for [a=1:4] '/tmp/relief_h3_plots/relief_quality.dat' index ((m-1)*4+a-1) every ::0::4 using 3:4 with linespoints lc a pt 7 title 'N=4..32 '.word(angles, a).' deg', \
       for [a=1:4] '' index ((m-1)*4+a-1) every ::5::5 using 3:4 with points lc a pt 9 ps 2 title (a == 1 ? 'adaptive' : ''), \
       for [a=1:4] '' index ((m-1)*4+a-1) every ::6::6 using 3:4 with points lc a pt 4 ps 1.5 title (a == 1 ? 'iter-seed' : ''), \
       for [a=1:4] '' index ((m-1)*4+a-1) every ::7::7 using 3:4 with points lc a pt 12 ps 1.5 title (a == 1 ? 'iter-norm' : '')
}
unset multiplot
