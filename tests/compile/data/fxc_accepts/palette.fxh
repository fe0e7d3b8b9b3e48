// Beside the main file: include_stack/parts/lighting.fxh must find include_stack/palette.fxh
// first (its includer's folder comes before the main file's).
#error "palette.fxh beside the main file was taken before the one beside material.fxh"
