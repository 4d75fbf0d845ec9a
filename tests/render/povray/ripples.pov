#include "stage.inc"
#declare P = pigment { ripples color_map { TwinColors } }
Wall(P)
