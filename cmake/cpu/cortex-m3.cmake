# Cortex-M3: no FPU; float arithmetic in software (libgcc's soft-float).
set(TREAD_CPU_FLAGS "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft")
set(CMAKE_C_FLAGS_INIT "${TREAD_CPU_FLAGS}")
set(CMAKE_CXX_FLAGS_INIT "${TREAD_CPU_FLAGS}")
set(CMAKE_ASM_FLAGS_INIT "${TREAD_CPU_FLAGS}")
