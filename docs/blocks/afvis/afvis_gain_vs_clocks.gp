set terminal pngcairo size 900,600
set output 'docs/blocks/afvis/afvis_gain_vs_clocks.png'
set title 'AF visibility: PSNR gain over plain EWA (relief pixels, vs truth) vs added clocks'
set xlabel 'added clocks per relief pixel (%, serial trace: one depth read per clock)'
set ylabel 'PSNR gain over POM + plain EWA (dB)'
set grid
set key outside right
set xzeroaxis lw 2
plot 'docs/blocks/afvis/afvis_gain_vs_clocks.dat' index 0 using 1:2 with points pt 5 ps 1.5 title 'every', 'docs/blocks/afvis/afvis_gain_vs_clocks.dat' index 1 using 1:2 with points pt 7 ps 1.5 title 'row', 'docs/blocks/afvis/afvis_gain_vs_clocks.dat' index 2 using 1:2 with points pt 9 ps 1.5 title 'pyramid2', 'docs/blocks/afvis/afvis_gain_vs_clocks.dat' index 3 using 1:2 with points pt 11 ps 1.5 title 'row+pyramid2', '' index 0 using 1:2:3 with labels offset 0,1 font ',8' notitle
