#include "stage.inc"
#declare P = pigment { gradient <1, 0.5, 0> color_map { TwinColors } frequency 0.6 phase 0.3 sine_wave }
Wall(P)
