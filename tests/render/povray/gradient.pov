#include "stage.inc"
#declare P = pigment { gradient <1, 1, 0> color_map { TwinColors } scale 1.7 }
Wall(P)
