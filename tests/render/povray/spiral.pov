#include "stage.inc"
#declare P = pigment { spiral1 3 color_map { TwinColors } scale 0.8 }
Wall(P)
