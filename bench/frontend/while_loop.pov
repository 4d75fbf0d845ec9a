// Front-end benchmark: while_loop (see bench/README.md).
// 1,000,000 iterations of four float operations (*, sin, *, +) plus the
// counter test and increment. Equivalent to while_loop.crt.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0.0, 0.0, -10.0> look_at <0.0, 0.0, 0.0> }
light_source { <0.0, 10.0, -10.0> color rgb <1.0, 1.0, 1.0> }

#declare X = 0.0;
#declare I = 0;
#while (I < 1000000)
    #declare X = X + sin(I * 0.001) * 0.5;
    #declare I = I + 1;
#end
#debug concat("x = ", str(X, 0, 9), "\n")

sphere { <0.0, 0.0, 0.0>, 1.0 pigment { color rgb <1.0, 1.0, 1.0> } }
