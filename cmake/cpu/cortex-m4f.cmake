# Cortex-M4 with single-precision FPU, hard-float ABI.
set(TREAD_CPU_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")
set(CMAKE_C_FLAGS_INIT "${TREAD_CPU_FLAGS}")
set(CMAKE_CXX_FLAGS_INIT "${TREAD_CPU_FLAGS}")
set(CMAKE_ASM_FLAGS_INIT "${TREAD_CPU_FLAGS}")
