// simd/simd.h -- for the host tests only: SPIRV-Cross's MSL includes it; what
// the kernels use of it (the vector types) is in ../metal_stdlib.
