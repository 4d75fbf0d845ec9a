#include "stage.inc"
#declare P = pigment { onion color_map { TwinColors } frequency 0.5 poly_wave 2.5 }
Wall(P)
