#include "stage.inc"
#declare P = pigment { planar color_map { TwinColors } scale 3 }
Wall(P)
