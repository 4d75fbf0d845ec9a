#include "stage.inc"
#declare P = pigment { waves color_map { TwinColors } }
Wall(P)
