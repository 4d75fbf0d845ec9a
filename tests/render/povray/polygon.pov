#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
polygon { 10, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <-1, -1, 0>,
              <-0.5, -0.5, 0>, <0.5, -0.5, 0>, <0.5, 0.5, 0>, <-0.5, 0.5, 0>, <-0.5, -0.5, 0>
          texture { pigment { color rgb <0.9, 0.6, 0.2> } finish { ambient 0 diffuse 1 } }
          scale 1.3 rotate <30, 20, 0> translate <-1.5, 1, -1> }
polygon { 10,
    #for (I, 0, 9)
        #local R = (mod(I, 2) = 0 ? 1.2 : 0.5);
        <R * cos(radians(I * 36)), R * sin(radians(I * 36)), 0>
    #end
    texture { pigment { color rgb <0.3, 0.6, 0.9> } finish { ambient 0 diffuse 1 } }
    rotate <-25, 35, 10> translate <1.6, -1.2, -1> }
