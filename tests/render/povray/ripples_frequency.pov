#include "stage.inc"
#declare P = pigment { ripples color_map { TwinColors } frequency 2 phase 0.3 scale 1.5 }
Wall(P)
