// Real files for PreprocessorIncludes.RealFilesOnDisk.
#include "common.fxh"
#include <lighting.fxh>
technique Main { }
