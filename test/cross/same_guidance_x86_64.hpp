// Generated on x86-64 (with FMA) by test/cross/same_guidance_test.cpp (EVADE_SAVE_SAME_GUIDANCE=FILE):
// the outputs every target must reproduce, in that test's order.
#pragma once

#include <vector>

namespace evade::test {

inline std::vector<double> table2_x86_64() {
  return {
    0x1.9004415aabebp+4, 0x1.3ffff4e8cc024p+3, 0x1.3ffff84b1d7eep+2,
    0x1.3ffff84b1d7eep+3, 0x1.f4p+8, 0x1.8ffc738b4dc08p+6,
    0x1.3fffbecba0676p+3, 0x1.3fffe116f8f2p+3, 0x1.3fffe116f8f2p+4,
    0x1.f4p+9, 0x1.c1f46a1a916c8p+7, 0x1.3fff2bdf6ff33p+3,
    0x1.dfff97a0e0b7ep+3, 0x1.dfff97a0e0b7ep+4, 0x1.77p+10,
    0x1.900139fa19dfcp+5, 0x1.3fffddc932c4bp+3, 0x1.3fffe12b84415p+3,
    0x1.3fffe12b84415p+3, 0x1.f4p+8, 0x1.8ffa929dea4a6p+7,
    0x1.3fff05806eb6ep+3, 0x1.3fff84716019cp+4, 0x1.3fff84716019cp+4,
    0x1.f4p+9, 0x1.c1f10631696ddp+8, 0x1.3ffcbaef88576p+3,
    0x1.dffe5f28eceap+4, 0x1.dffe5f28eceap+4, 0x1.77p+10,
    0x1.2bffe17683601p+6, 0x1.3fffb747ee528p+3, 0x1.dfff97ff5fb96p+3,
    0x1.3fffbaaa3fcf2p+3, 0x1.f4p+8, 0x1.2bfa4ba2132a7p+8,
    0x1.3ffdd1266cdc5p+3, 0x1.dffe5f668eca9p+4, 0x1.3ffeea445f2c8p+4,
    0x1.f4p+9, 0x1.517118609f1f7p+9, 0x1.3ff8abcd17447p+3,
    0x1.67fd41b1c7537p+5, 0x1.dffc5797b4608p+4, 0x1.77p+10,
    0x1.8ffebe51f65d2p+6, 0x1.3fff815bc52aap+3, 0x1.3fff84be16a74p+4,
    0x1.3fff84be16a74p+3, 0x1.f4p+8, 0x1.8ff5b167d446dp+8,
    0x1.3ffc2214e7efap+3, 0x1.3ffe12bb9cb62p+5, 0x1.3ffe12bb9cb62p+4,
    0x1.f4p+9, 0x1.c1e5a7cf505fbp+9, 0x1.3ff3009a5d9e4p+3,
    0x1.dff981fe578d7p+5, 0x1.dff981fe578d7p+4, 0x1.77p+10,
  };
}

inline std::vector<double> seed4_run_x86_64() {
  return {
    0x1p+0, 0x1.1p+3, 0x1.7p+3,
    0x1.7e59e49327c85p+1, -0x1.1c5c90e597fd2p-2, 0x1.ffa309f31c1e2p-28,
    0x1.57f421b81fd8p+21, 0x1.7867784e03fc4p+22, 0x1.8fb99a74becaap-18,
    -0x1.b3c4e85d1336ep+12, 0x1.8e4c3d8c8b90dp+11, 0x1.b3b2f4331baf3p-29,
    0x1.3b0e060bb8779p+21, 0x1.7046dba87dad7p+22, 0x0p+0,
    -0x1.c284077bf203ap+12, 0x1.5f4cf898daa45p+11, 0x0p+0,
    0x1.4p+3, 0x1.9dada14efae0bp+22, 0x1.2b8bd72560bbbp+16,
    0x1.7fbb910f20d14p-29, -0x1.550e8ebde7594p+6, 0x1.df3ed62485797p+12,
    0x1.ffa448cfa68dep-29, 0x1.98c41cd29542cp+22, 0x1.03bbfc5414c34p+17,
    0x0p+0, -0x1.1ce1a2c7a016cp+7, 0x1.d967b95f68619p+12,
    0x0p+0, 0x1.f9p+9, 0x1.57f421b81fd8p+21,
    0x1.7867784e03fc4p+22, 0x1.8fb99a74becaap-18, -0x1.b3c4e85d1336ep+12,
    0x1.8e4c3d8c8b90dp+11, 0x1.b3b2f4331baf3p-29, 0x1.3b0e060bb8779p+21,
    0x1.7046dba87dad7p+22, 0x0p+0, -0x1.c284077bf203ap+12,
    0x1.5f4cf898daa45p+11, 0x0p+0, 0x1.8a88p+15,
  };
}

inline std::vector<double> seed3_run_x86_64() {
  return {
    0x1p+1, 0x1.517ep+15, 0x1.518p+15,
    -0x1.061e909aa2365p-9, 0x1.3e387ee6142dfp-8, 0x1.45288f488d64p-9,
    0x1.274f8p+17, 0x1.275p+17, -0x1.768b1672d99f5p-10,
    -0x1.17e447fac79ebp-8, 0x1.dfb1b486dc75ap-9, 0x1.5bfe5b66c7cffp+21,
    -0x1.3330607174ee6p+22, -0x1.20f86cc7bd5a2p+22, 0x1.c5ed2d8c30ac5p+10,
    0x1.4f72dd388cc39p+12, -0x1.1fcf636f56e97p+12, 0x1.5c0d05bc6487dp+21,
    -0x1.331a6c1aff627p+22, -0x1.210b1a6064b72p+22, 0x1.c5c047f789dd6p+10,
    0x1.4f86da812e0c8p+12, -0x1.1fbcb4a7dc6a4p+12, 0x1.a5ep+16,
    0x1.0b566230f148cp+20, 0x1.8739fc74d0c86p+22, -0x1.c15a270c61da8p+21,
    -0x1.8e14e0d28043cp+11, 0x1.cb90760ba5a81p+11, 0x1.54a5580af469cp+12,
    0x1.0b37f21ebab8ap+20, 0x1.8742c1f5d67a5p+22, -0x1.c1400f102c135p+21,
    -0x1.8e19f36fa32a4p+11, 0x1.cb724302175d6p+11, 0x1.54adf6c7c13f4p+12,
    0x1.33de8p+17, 0x1.5bfe5b66c7cffp+21, -0x1.3330607174ee6p+22,
    -0x1.20f86cc7bd5a2p+22, 0x1.c5ed2d8c30ac5p+10, 0x1.4f72dd388cc39p+12,
    -0x1.1fcf636f56e97p+12, 0x1.5c0d05bc6487dp+21, -0x1.331a6c1aff627p+22,
    -0x1.210b1a6064b72p+22, 0x1.c5c047f789dd6p+10, 0x1.4f86da812e0c8p+12,
    -0x1.1fbcb4a7dc6a4p+12, 0x1.33de8p+17,
  };
}

}  // namespace evade::test
