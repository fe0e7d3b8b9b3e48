struct Material { float4 colour; texture diffuse; };
Material m;
float x < int a = 1, b = a; static string s = "x"; texture t = 0; >;
fxgroup G { technique11 T { pass P { } } }
