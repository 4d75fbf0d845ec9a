#include "stage.inc"
#declare P = pigment { onion color_map { TwinColors } scale 0.9 }
Wall(P)
