#include "stage.inc"
#declare P = pigment { spherical color_map { TwinColors } scale 3.5 }
Wall(P)
