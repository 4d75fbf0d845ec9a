#include "stage.inc"
#declare P = pigment { mandel 40 color_map { TwinColors } scale 1.4 translate -0.6*x }
Wall(P)
