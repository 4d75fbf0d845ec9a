#include "stage.inc"
#declare P = pigment { leopard color_map { TwinColors } scale 0.15 }
Wall(P)
