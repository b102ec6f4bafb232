%
(cncsim G-code corpus: fusion_2d_adaptive.nc)
(Imitates the output of an Autodesk Fusion 360 milling post processor. Written by hand for cncsim: not Fusion output.)
(Exercises: the % tape markers, the tool comment, G90 G94 G17, G21, G28 G91 Z0. then G90 at start and end, T1 M6,)
(S8000 M3, G54, M8 and M9, numbers with a trailing point and 3 decimals, G0 Z5., G1 Z-1. F300., an adaptive slot)
(of 20 trochoidal G3 loops, a climb profile with G2 corners, G3 lead-in and lead-out arcs at 60 degrees, M30)
(T1 D=3 CR=0 - ZMIN=-1 - flat end mill)
G90 G94 G17
G21
G28 G91 Z0.
G90

(2D Adaptive1)
T1 M6
S8000 M3
G54
M8
G0 X112. Y115.
G0 Z5.
G1 Z-1. F300.
G3 X108. I-2. J0. F1000.
G3 X112. I2. J0.
G1 X112.8
G3 X108.8 I-2. J0.
G3 X112.8 I2. J0.
G1 X113.6
G3 X109.6 I-2. J0.
G3 X113.6 I2. J0.
G1 X114.4
G3 X110.4 I-2. J0.
G3 X114.4 I2. J0.
G1 X115.2
G3 X111.2 I-2. J0.
G3 X115.2 I2. J0.
G1 X116.
G3 X112. I-2. J0.
G3 X116. I2. J0.
G1 X116.8
G3 X112.8 I-2. J0.
G3 X116.8 I2. J0.
G1 X117.6
G3 X113.6 I-2. J0.
G3 X117.6 I2. J0.
G1 X118.4
G3 X114.4 I-2. J0.
G3 X118.4 I2. J0.
G1 X119.2
G3 X115.2 I-2. J0.
G3 X119.2 I2. J0.
G1 X120.
G3 X116. I-2. J0.
G3 X120. I2. J0.
G1 X120.8
G3 X116.8 I-2. J0.
G3 X120.8 I2. J0.
G1 X121.6
G3 X117.6 I-2. J0.
G3 X121.6 I2. J0.
G1 X122.4
G3 X118.4 I-2. J0.
G3 X122.4 I2. J0.
G1 X123.2
G3 X119.2 I-2. J0.
G3 X123.2 I2. J0.
G1 X124.
G3 X120. I-2. J0.
G3 X124. I2. J0.
G1 X124.8
G3 X120.8 I-2. J0.
G3 X124.8 I2. J0.
G1 X125.6
G3 X121.6 I-2. J0.
G3 X125.6 I2. J0.
G1 X126.4
G3 X122.4 I-2. J0.
G3 X126.4 I2. J0.
G1 X127.2
G3 X123.2 I-2. J0.
G3 X127.2 I2. J0.
G0 Z5.

(2D Contour1)
G0 X98.5 Y112.402
G1 Z-1. F300.
G3 X100. Y115. I-1.5 J2.598 F1000.
G1 Y126.
G2 X104. Y130. I4. J0.
G1 X136.
G2 X140. Y126. I0. J-4.
G1 Y104.
G2 X136. Y100. I-4. J0.
G1 X104.
G2 X100. Y104. I0. J4.
G1 Y115.
G3 X98.5 Y117.598 I-3. J0.
G0 Z5.
M9
G28 G91 Z0.
G90
M30
%
