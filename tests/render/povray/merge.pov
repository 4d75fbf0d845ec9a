#include "stage.inc"
#declare P = pigment { gradient x color_map { TwinColors } scale 3 }
Wall(P)
#declare See = texture { pigment { rgbt <0.9, 0.5, 0.2, 0.5> } finish { ambient 0 diffuse 1 } }
merge { sphere { <-2.1, 0.4, -1>, 1 } sphere { <-1.3, -0.4, -1>, 1 } texture { See } }
union { sphere { <1.3, 0.4, -1>, 1 } sphere { <2.1, -0.4, -1>, 1 } texture { See } }
