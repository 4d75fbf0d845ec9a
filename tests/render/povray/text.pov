#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#declare Red = texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }
#declare Blue = texture { pigment { color rgb <0.3, 0.4, 0.95> } finish { ambient 0 diffuse 1 } }
text { ttf "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf" "AVTag 8B" 0.25, 0
       texture { Red } scale 1.15 rotate <-20, 20, 0> translate <-2.7, 0.7, -1> }
text { ttf "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf" "Sea, jolly!" 0.5, 0
       texture { Blue } scale 0.95 rotate <15, 15, 0> translate <-2.6, -1.9, -1> }
