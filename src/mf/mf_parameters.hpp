#pragma once
// Magic Formula parameters (MF-Tyre 5.2, MF 6.1, MF 6.2, and PAC2002 steady state): one plain
// struct, templated on the scalar (float on the ECU, double on the host, ceres::Jet in the fitter).
//
// Every coefficient comes from one list, TREAD_MF_PARAMETER_LIST(X), with one row per .tir key:
//   X(member, "SECTION", "KEY", default, "description")
// The defaults are MFeval 4.3.1's: a key missing from a .tir file takes the Pacejka-book 205/60R15
// value (data/tyres/PacejkaBook_Defaults.tir). Keys that file does not have (the MF 5.2
// and MF 6.2 extras) default to 0, scale factors to 1. One exception, found against MFeval's
// output: LONGITUDINAL_STIFFNESS defaults to 300000 N/m (MFeval's Cx for a file without the key),
// not the book file's 400000. Members carry units where they have one (fnomin_n,
// unloaded_radius_m); dimensionless Magic Formula coefficients keep their TNO name.
//
// The list drives the struct, the .tir mapping (sim/tyre/mf_parameters_from_tir.cpp), the
// scalar conversion below and the constexpr header generator: add a key here and all follow.

#include <cstdint>

namespace tread::mf {

// clang-format off
#define TREAD_MF_PARAMETER_LIST(X) \
  /* [MODEL] */ \
  X(longvl_mps, "MODEL", "LONGVL", 16.7, "Nominal speed") \
  X(vxlow_mps, "MODEL", "VXLOW", 1.0, "Lower boundary of slip calculation") \
  /* [DIMENSION] */ \
  X(unloaded_radius_m, "DIMENSION", "UNLOADED_RADIUS", 0.3135, "Free tyre radius") \
  X(width_m, "DIMENSION", "WIDTH", 0.205, "Nominal section width of the tyre") \
  X(aspect_ratio, "DIMENSION", "ASPECT_RATIO", 0.6, "Nominal aspect ratio") \
  X(rim_radius_m, "DIMENSION", "RIM_RADIUS", 0.1905, "Nominal rim radius") \
  /* [OPERATING_CONDITIONS] */ \
  X(inflpres_pa, "OPERATING_CONDITIONS", "INFLPRES", 220000.0, "Tyre inflation pressure - Modify this parameter to change inflation pressure") \
  X(nompres_pa, "OPERATING_CONDITIONS", "NOMPRES", 220000.0, "Nominal tyre inflation pressure - NEVER MODIFY THIS PARAMETER") \
  /* [VERTICAL] */ \
  X(fnomin_n, "VERTICAL", "FNOMIN", 4000.0, "Nominal wheel load") \
  X(vertical_stiffness_npm, "VERTICAL", "VERTICAL_STIFFNESS", 200000.0, "Tyre vertical stiffness") \
  X(breff, "VERTICAL", "BREFF", 8.0, "Low load stiffness effective rolling radius") \
  X(dreff, "VERTICAL", "DREFF", 0.24, "Peak value of effective rolling radius") \
  X(freff, "VERTICAL", "FREFF", 0.01, "High load stiffness effective rolling radius") \
  X(q_re0, "VERTICAL", "Q_RE0", 1.0, "Ratio of free tyre radius with nominal tyre radius") \
  X(q_v1, "VERTICAL", "Q_V1", 0.0, "Tyre radius increase with speed") \
  X(q_v2, "VERTICAL", "Q_V2", 0.0, "Vertical stiffness increase with speed") \
  X(q_fz2, "VERTICAL", "Q_FZ2", 0.0, "Quadratic term in load vs. deflection") \
  X(q_fcx, "VERTICAL", "Q_FCX", 0.0, "Longitudinal force influence on vertical stiffness") \
  X(q_fcy, "VERTICAL", "Q_FCY", 0.0, "Lateral force influence on vertical stiffness") \
  X(pfz1, "VERTICAL", "PFZ1", 0.8, "Pressure effect on vertical stiffness") \
  X(bottom_offst_m, "VERTICAL", "BOTTOM_OFFST", 0.01, "Distance to rim when bottoming starts to occur") \
  X(q_fcy2, "VERTICAL", "Q_FCY2", 0.0, "MF6.2 explicit load dependency of Fy influence on vertical stiffness") \
  X(q_cam1, "VERTICAL", "Q_CAM1", 0.0, "MF6.2 linear load dependent camber influence on vertical stiffness") \
  X(q_cam2, "VERTICAL", "Q_CAM2", 0.0, "MF6.2 quadratic load dependent camber influence on vertical stiffness") \
  X(q_cam3, "VERTICAL", "Q_CAM3", 0.0, "MF6.2 load and camber dependent reduction of vertical stiffness") \
  X(q_fys1, "VERTICAL", "Q_FYS1", 0.0, "MF6.2 camber and side slip effect on vertical stiffness (constant)") \
  X(q_fys2, "VERTICAL", "Q_FYS2", 0.0, "MF6.2 camber and side slip effect on vertical stiffness (linear)") \
  X(q_fys3, "VERTICAL", "Q_FYS3", 0.0, "MF6.2 camber and side slip effect on vertical stiffness (quadratic)") \
  /* [STRUCTURAL] */ \
  X(longitudinal_stiffness_npm, "STRUCTURAL", "LONGITUDINAL_STIFFNESS", 300000.0, "Tyre overall longitudinal stiffness") \
  X(lateral_stiffness_npm, "STRUCTURAL", "LATERAL_STIFFNESS", 100000.0, "Tyre overall lateral stiffness") \
  X(pcfx1, "STRUCTURAL", "PCFX1", 0.0, "Tyre overall longitudinal stiffness vertical deflection dependency linear term") \
  X(pcfx2, "STRUCTURAL", "PCFX2", 0.0, "Tyre overall longitudinal stiffness vertical deflection dependency quadratic term") \
  X(pcfx3, "STRUCTURAL", "PCFX3", 0.2, "Tyre overall longitudinal stiffness pressure dependency") \
  X(pcfy1, "STRUCTURAL", "PCFY1", 0.0, "Tyre overall lateral stiffness vertical deflection dependency linear term") \
  X(pcfy2, "STRUCTURAL", "PCFY2", 0.0, "Tyre overall lateral stiffness vertical deflection dependency quadratic term") \
  X(pcfy3, "STRUCTURAL", "PCFY3", 0.5, "Tyre overall lateral stiffness pressure dependency") \
  /* [CONTACT_PATCH] */ \
  X(q_ra1, "CONTACT_PATCH", "Q_RA1", 0.79, "Square root term in contact length equation") \
  X(q_ra2, "CONTACT_PATCH", "Q_RA2", 0.35, "Linear term in contact length equation") \
  X(q_rb1, "CONTACT_PATCH", "Q_RB1", 1.0, "Root term in contact width equation") \
  X(q_rb2, "CONTACT_PATCH", "Q_RB2", -1.0, "Linear term in contact width equation") \
  X(q_a1, "CONTACT_PATCH", "Q_A1", 0.0, "MF5.2 square root load term in contact length (0 with Q_A2 = 0: MFeval fallback)") \
  X(q_a2, "CONTACT_PATCH", "Q_A2", 0.0, "MF5.2 linear load term in contact length") \
  /* [INFLATION_PRESSURE_RANGE] */ \
  X(presmin_pa, "INFLATION_PRESSURE_RANGE", "PRESMIN", 10000.0, "Minimum valid tyre inflation pressure") \
  X(presmax_pa, "INFLATION_PRESSURE_RANGE", "PRESMAX", 1000000.0, "Maximum valid tyre inflation pressure") \
  /* [VERTICAL_FORCE_RANGE] */ \
  X(fzmin_n, "VERTICAL_FORCE_RANGE", "FZMIN", 100.0, "Minimum allowed wheel load") \
  X(fzmax_n, "VERTICAL_FORCE_RANGE", "FZMAX", 10000.0, "Maximum allowed wheel load") \
  /* [LONG_SLIP_RANGE] */ \
  X(kpumin, "LONG_SLIP_RANGE", "KPUMIN", -1.5, "Minimum valid wheel slip") \
  X(kpumax, "LONG_SLIP_RANGE", "KPUMAX", 1.5, "Maximum valid wheel slip") \
  /* [SLIP_ANGLE_RANGE] */ \
  X(alpmin_rad, "SLIP_ANGLE_RANGE", "ALPMIN", -1.5, "Minimum valid slip angle") \
  X(alpmax_rad, "SLIP_ANGLE_RANGE", "ALPMAX", 1.5, "Maximum valid slip angle") \
  /* [INCLINATION_ANGLE_RANGE] */ \
  X(cammin_rad, "INCLINATION_ANGLE_RANGE", "CAMMIN", -0.175, "Minimum valid camber angle") \
  X(cammax_rad, "INCLINATION_ANGLE_RANGE", "CAMMAX", 0.175, "Maximum valid camber angle") \
  /* [SCALING_COEFFICIENTS] */ \
  X(lfzo, "SCALING_COEFFICIENTS", "LFZO", 1.0, "Scale factor of nominal (rated) load") \
  X(lcx, "SCALING_COEFFICIENTS", "LCX", 1.0, "Scale factor of Fx shape factor") \
  X(lmux, "SCALING_COEFFICIENTS", "LMUX", 1.0, "Scale factor of Fx peak friction coefficient") \
  X(lex, "SCALING_COEFFICIENTS", "LEX", 1.0, "Scale factor of Fx curvature factor") \
  X(lkx, "SCALING_COEFFICIENTS", "LKX", 1.0, "Scale factor of Fx slip stiffness") \
  X(lhx, "SCALING_COEFFICIENTS", "LHX", 1.0, "Scale factor of Fx horizontal shift") \
  X(lvx, "SCALING_COEFFICIENTS", "LVX", 1.0, "Scale factor of Fx vertical shift") \
  X(lcy, "SCALING_COEFFICIENTS", "LCY", 1.0, "Scale factor of Fy shape factor") \
  X(lmuy, "SCALING_COEFFICIENTS", "LMUY", 1.0, "Scale factor of Fy peak friction coefficient") \
  X(ley, "SCALING_COEFFICIENTS", "LEY", 1.0, "Scale factor of Fy curvature factor") \
  X(lky, "SCALING_COEFFICIENTS", "LKY", 1.0, "Scale factor of Fy cornering stiffness") \
  X(lhy, "SCALING_COEFFICIENTS", "LHY", 1.0, "Scale factor of Fy horizontal shift") \
  X(lvy, "SCALING_COEFFICIENTS", "LVY", 1.0, "Scale factor of Fy vertical shift") \
  X(ltr, "SCALING_COEFFICIENTS", "LTR", 1.0, "Scale factor of peak of pneumatic trail") \
  X(lres, "SCALING_COEFFICIENTS", "LRES", 1.0, "Scale factor for offset of residual torque") \
  X(lxal, "SCALING_COEFFICIENTS", "LXAL", 1.0, "Scale factor of alpha influence on Fx") \
  X(lyka, "SCALING_COEFFICIENTS", "LYKA", 1.0, "Scale factor of kappa influence on Fy") \
  X(lvyka, "SCALING_COEFFICIENTS", "LVYKA", 1.0, "Scale factor of kappa induced Fy") \
  X(ls, "SCALING_COEFFICIENTS", "LS", 1.0, "Scale factor of moment arm of Fx") \
  X(lkyc, "SCALING_COEFFICIENTS", "LKYC", 1.0, "Scale factor of camber force stiffness") \
  X(lkzc, "SCALING_COEFFICIENTS", "LKZC", 1.0, "Scale factor of camber torque stiffness") \
  X(lvmx, "SCALING_COEFFICIENTS", "LVMX", 1.0, "Scale factor of Mx vertical shift") \
  X(lmx, "SCALING_COEFFICIENTS", "LMX", 1.0, "Scale factor of overturning couple") \
  X(lmy, "SCALING_COEFFICIENTS", "LMY", 1.0, "Scale factor of rolling resistance torque") \
  X(lmp, "SCALING_COEFFICIENTS", "LMP", 1.0, "Scale factor of Parking Moment") \
  X(lgax, "SCALING_COEFFICIENTS", "LGAX", 1.0, "PAC2002 scale factor of camber for Fx") \
  X(lgay, "SCALING_COEFFICIENTS", "LGAY", 1.0, "PAC2002 scale factor of camber for Fy") \
  X(lgaz, "SCALING_COEFFICIENTS", "LGAZ", 1.0, "PAC2002 scale factor of camber for Mz") \
  X(lsgkp, "SCALING_COEFFICIENTS", "LSGKP", 1.0, "MF5.2 scale factor of relaxation length of Fx") \
  X(lsgal, "SCALING_COEFFICIENTS", "LSGAL", 1.0, "MF5.2 scale factor of relaxation length of Fy") \
  /* [LONGITUDINAL_COEFFICIENTS] */ \
  X(pcx1, "LONGITUDINAL_COEFFICIENTS", "PCX1", 1.6, "Shape factor Cfx for longitudinal force") \
  X(pdx1, "LONGITUDINAL_COEFFICIENTS", "PDX1", 1.0, "Longitudinal friction Mux at Fznom") \
  X(pdx2, "LONGITUDINAL_COEFFICIENTS", "PDX2", -0.1, "Variation of friction Mux with load") \
  X(pdx3, "LONGITUDINAL_COEFFICIENTS", "PDX3", 0.0, "Variation of friction Mux with camber squared") \
  X(pex1, "LONGITUDINAL_COEFFICIENTS", "PEX1", 0.0, "Longitudinal curvature Efx at Fznom") \
  X(pex2, "LONGITUDINAL_COEFFICIENTS", "PEX2", 0.0, "Variation of curvature Efx with load") \
  X(pex3, "LONGITUDINAL_COEFFICIENTS", "PEX3", 0.0, "Variation of curvature Efx with load squared") \
  X(pex4, "LONGITUDINAL_COEFFICIENTS", "PEX4", 0.0, "Factor in curvature Efx while driving") \
  X(pkx1, "LONGITUDINAL_COEFFICIENTS", "PKX1", 16.0, "Longitudinal slip stiffness Kfx/Fz at Fznom") \
  X(pkx2, "LONGITUDINAL_COEFFICIENTS", "PKX2", 0.0, "Variation of slip stiffness Kfx/Fz with load") \
  X(pkx3, "LONGITUDINAL_COEFFICIENTS", "PKX3", 0.0, "Exponent in slip stiffness Kfx/Fz with load") \
  X(phx1, "LONGITUDINAL_COEFFICIENTS", "PHX1", 0.0, "Horizontal shift Shx at Fznom") \
  X(phx2, "LONGITUDINAL_COEFFICIENTS", "PHX2", 0.0, "Variation of shift Shx with load") \
  X(pvx1, "LONGITUDINAL_COEFFICIENTS", "PVX1", 0.0, "Vertical shift Svx/Fz at Fznom") \
  X(pvx2, "LONGITUDINAL_COEFFICIENTS", "PVX2", 0.0, "Variation of shift Svx/Fz with load") \
  X(ppx1, "LONGITUDINAL_COEFFICIENTS", "PPX1", 0.0, "linear influence of inflation pressure on longitudinal slip stiffness") \
  X(ppx2, "LONGITUDINAL_COEFFICIENTS", "PPX2", 0.0, "quadratic influence of inflation pressure on longitudinal slip stiffness") \
  X(ppx3, "LONGITUDINAL_COEFFICIENTS", "PPX3", 0.0, "linear influence of inflation pressure on peak longitudinal friction") \
  X(ppx4, "LONGITUDINAL_COEFFICIENTS", "PPX4", 0.0, "quadratic influence of inflation pressure on peak longitudinal friction") \
  X(rbx1, "LONGITUDINAL_COEFFICIENTS", "RBX1", 8.3, "Slope factor for combined slip Fx reduction") \
  X(rbx2, "LONGITUDINAL_COEFFICIENTS", "RBX2", 5.0, "Variation of slope Fx reduction with kappa") \
  X(rbx3, "LONGITUDINAL_COEFFICIENTS", "RBX3", 0.0, "Influence of camber on stiffness for Fx combined") \
  X(rcx1, "LONGITUDINAL_COEFFICIENTS", "RCX1", 0.9, "Shape factor for combined slip Fx reduction") \
  X(rex1, "LONGITUDINAL_COEFFICIENTS", "REX1", 0.0, "Curvature factor of combined Fx") \
  X(rex2, "LONGITUDINAL_COEFFICIENTS", "REX2", 0.0, "Curvature factor of combined Fx with load") \
  X(rhx1, "LONGITUDINAL_COEFFICIENTS", "RHX1", 0.0, "Shift factor for combined slip Fx reduction") \
  X(ptx1, "LONGITUDINAL_COEFFICIENTS", "PTX1", 0.0, "MF5.2 relaxation length SigKap0/Fz at Fznom") \
  X(ptx2, "LONGITUDINAL_COEFFICIENTS", "PTX2", 0.0, "MF5.2 variation of SigKap0/Fz with load") \
  X(ptx3, "LONGITUDINAL_COEFFICIENTS", "PTX3", 0.0, "MF5.2 variation of SigKap0/Fz with exponent of load") \
  /* [OVERTURNING_COEFFICIENTS] */ \
  X(qsx1, "OVERTURNING_COEFFICIENTS", "QSX1", 0.0, "Vertical shift of overturning moment") \
  X(qsx2, "OVERTURNING_COEFFICIENTS", "QSX2", 0.0, "Camber induced overturning couple") \
  X(qsx3, "OVERTURNING_COEFFICIENTS", "QSX3", 0.0, "Fy induced overturning couple") \
  X(qsx4, "OVERTURNING_COEFFICIENTS", "QSX4", 5.0, "Mixed load lateral force and camber on Mx") \
  X(qsx5, "OVERTURNING_COEFFICIENTS", "QSX5", 1.0, "Load effect on Mx with lateral force and camber") \
  X(qsx6, "OVERTURNING_COEFFICIENTS", "QSX6", 10.0, "B-factor of load with Mx") \
  X(qsx7, "OVERTURNING_COEFFICIENTS", "QSX7", 0.0, "Camber with load on Mx") \
  X(qsx8, "OVERTURNING_COEFFICIENTS", "QSX8", 0.0, "Lateral force with load on Mx") \
  X(qsx9, "OVERTURNING_COEFFICIENTS", "QSX9", 0.4, "B-factor of lateral force with load on Mx") \
  X(qsx10, "OVERTURNING_COEFFICIENTS", "QSX10", 0.0, "Vertical force with camber on Mx") \
  X(qsx11, "OVERTURNING_COEFFICIENTS", "QSX11", 5.0, "B-factor of vertical force with camber on Mx") \
  X(qsx12, "OVERTURNING_COEFFICIENTS", "QSX12", 0.0, "Camber squared induced overturning moment") \
  X(qsx13, "OVERTURNING_COEFFICIENTS", "QSX13", 0.0, "Lateral force induced overturning moment") \
  X(qsx14, "OVERTURNING_COEFFICIENTS", "QSX14", 0.0, "Lateral force induced overturning moment with camber") \
  X(ppmx1, "OVERTURNING_COEFFICIENTS", "PPMX1", 0.0, "Influence of inflation pressure on overturning moment") \
  /* [LATERAL_COEFFICIENTS] */ \
  X(pcy1, "LATERAL_COEFFICIENTS", "PCY1", 1.3, "Shape factor Cfy for lateral forces") \
  X(pdy1, "LATERAL_COEFFICIENTS", "PDY1", 1.0, "Lateral friction Muy") \
  X(pdy2, "LATERAL_COEFFICIENTS", "PDY2", -0.05, "Variation of friction Muy with load") \
  X(pdy3, "LATERAL_COEFFICIENTS", "PDY3", 0.0, "Variation of friction Muy with squared camber") \
  X(pey1, "LATERAL_COEFFICIENTS", "PEY1", 0.0, "Lateral curvature Efy at Fznom") \
  X(pey2, "LATERAL_COEFFICIENTS", "PEY2", 0.0, "Variation of curvature Efy with load") \
  X(pey3, "LATERAL_COEFFICIENTS", "PEY3", 0.0, "Zero order camber dependency of curvature Efy") \
  X(pey4, "LATERAL_COEFFICIENTS", "PEY4", 0.0, "Variation of curvature Efy with camber") \
  X(pey5, "LATERAL_COEFFICIENTS", "PEY5", 0.0, "Variation of curvature Efy with camber squared") \
  X(pky1, "LATERAL_COEFFICIENTS", "PKY1", -15.0, "Maximum value of stiffness Kfy/Fznom") \
  X(pky2, "LATERAL_COEFFICIENTS", "PKY2", 2.0, "Load at which Kfy reaches maximum value") \
  X(pky3, "LATERAL_COEFFICIENTS", "PKY3", 0.0, "Variation of Kfy/Fznom with camber") \
  X(pky4, "LATERAL_COEFFICIENTS", "PKY4", 2.0, "Curvature of stiffness Kfy") \
  X(pky5, "LATERAL_COEFFICIENTS", "PKY5", 0.0, "Peak stiffness variation with camber squared") \
  X(pky6, "LATERAL_COEFFICIENTS", "PKY6", -1.0, "Fy camber stiffness factor") \
  X(pky7, "LATERAL_COEFFICIENTS", "PKY7", 0.0, "Vertical load dependency of camber stiffness") \
  X(phy1, "LATERAL_COEFFICIENTS", "PHY1", 0.0, "Horizontal shift Shy at Fznom") \
  X(phy2, "LATERAL_COEFFICIENTS", "PHY2", 0.0, "Variation of shift Shy with load") \
  X(phy3, "LATERAL_COEFFICIENTS", "PHY3", 0.0, "MF5.2 variation of shift Shy with camber") \
  X(pvy1, "LATERAL_COEFFICIENTS", "PVY1", 0.0, "Vertical shift in Svy/Fz at Fznom") \
  X(pvy2, "LATERAL_COEFFICIENTS", "PVY2", 0.0, "Variation of shift Svy/Fz with load") \
  X(pvy3, "LATERAL_COEFFICIENTS", "PVY3", 0.0, "Variation of shift Svy/Fz with camber") \
  X(pvy4, "LATERAL_COEFFICIENTS", "PVY4", 0.0, "Variation of shift Svy/Fz with camber and load") \
  X(ppy1, "LATERAL_COEFFICIENTS", "PPY1", 0.0, "influence of inflation pressure on cornering stiffness") \
  X(ppy2, "LATERAL_COEFFICIENTS", "PPY2", 0.0, "influence of inflation pressure on dependency of nominal tyre load on cornering stiffness") \
  X(ppy3, "LATERAL_COEFFICIENTS", "PPY3", 0.0, "linear influence of inflation pressure on lateral peak friction") \
  X(ppy4, "LATERAL_COEFFICIENTS", "PPY4", 0.0, "quadratic influence of inflation pressure on lateral peak friction") \
  X(ppy5, "LATERAL_COEFFICIENTS", "PPY5", 0.0, "Influence of inflation pressure on camber stiffness") \
  X(rby1, "LATERAL_COEFFICIENTS", "RBY1", 4.9, "Slope factor for combined Fy reduction") \
  X(rby2, "LATERAL_COEFFICIENTS", "RBY2", 2.2, "Variation of slope Fy reduction with alpha") \
  X(rby3, "LATERAL_COEFFICIENTS", "RBY3", 0.0, "Shift term for alpha in slope Fy reduction") \
  X(rby4, "LATERAL_COEFFICIENTS", "RBY4", 0.0, "Influence of camber on stiffness of Fy combined") \
  X(rcy1, "LATERAL_COEFFICIENTS", "RCY1", 1.0, "Shape factor for combined Fy reduction") \
  X(rey1, "LATERAL_COEFFICIENTS", "REY1", 0.0, "Curvature factor of combined Fy") \
  X(rey2, "LATERAL_COEFFICIENTS", "REY2", 0.0, "Curvature factor of combined Fy with load") \
  X(rhy1, "LATERAL_COEFFICIENTS", "RHY1", 0.0, "Shift factor for combined Fy reduction") \
  X(rhy2, "LATERAL_COEFFICIENTS", "RHY2", 0.0, "Shift factor for combined Fy reduction with load") \
  X(rvy1, "LATERAL_COEFFICIENTS", "RVY1", 0.0, "Kappa induced side force Svyk/Muy*Fz at Fznom") \
  X(rvy2, "LATERAL_COEFFICIENTS", "RVY2", 0.0, "Variation of Svyk/Muy*Fz with load") \
  X(rvy3, "LATERAL_COEFFICIENTS", "RVY3", 0.0, "Variation of Svyk/Muy*Fz with camber") \
  X(rvy4, "LATERAL_COEFFICIENTS", "RVY4", 20.0, "Variation of Svyk/Muy*Fz with alpha") \
  X(rvy5, "LATERAL_COEFFICIENTS", "RVY5", 2.0, "Variation of Svyk/Muy*Fz with kappa") \
  X(rvy6, "LATERAL_COEFFICIENTS", "RVY6", 10.0, "Variation of Svyk/Muy*Fz with atan(kappa)") \
  X(pty1, "LATERAL_COEFFICIENTS", "PTY1", 0.0, "MF5.2 peak value of relaxation length SigAlp0/R0") \
  X(pty2, "LATERAL_COEFFICIENTS", "PTY2", 0.0, "MF5.2 value of Fz/Fznom where SigAlp0 is extreme") \
  /* [ROLLING_COEFFICIENTS] */ \
  X(qsy1, "ROLLING_COEFFICIENTS", "QSY1", 0.01, "Rolling resistance torque coefficien") \
  X(qsy2, "ROLLING_COEFFICIENTS", "QSY2", 0.0, "Rolling resistance torque depending on Fx") \
  X(qsy3, "ROLLING_COEFFICIENTS", "QSY3", 0.0004, "Rolling resistance torque depending on speed") \
  X(qsy4, "ROLLING_COEFFICIENTS", "QSY4", 4e-05, "Rolling resistance torque depending on speed ^4") \
  X(qsy5, "ROLLING_COEFFICIENTS", "QSY5", 0.0, "Rolling resistance torque depending on camber squared") \
  X(qsy6, "ROLLING_COEFFICIENTS", "QSY6", 0.0, "Rolling resistance torque depending on load and camber squared") \
  X(qsy7, "ROLLING_COEFFICIENTS", "QSY7", 0.85, "Rolling resistance torque coefficient load dependency") \
  X(qsy8, "ROLLING_COEFFICIENTS", "QSY8", -0.4, "Rolling resistance torque coefficient pressure dependency") \
  /* [ALIGNING_COEFFICIENTS] */ \
  X(qbz1, "ALIGNING_COEFFICIENTS", "QBZ1", 10.0, "Trail slope factor for trail Bpt at Fznom") \
  X(qbz2, "ALIGNING_COEFFICIENTS", "QBZ2", 0.0, "Variation of slope Bpt with load") \
  X(qbz3, "ALIGNING_COEFFICIENTS", "QBZ3", 0.0, "Variation of slope Bpt with load squared") \
  X(qbz4, "ALIGNING_COEFFICIENTS", "QBZ4", 0.0, "Variation of slope Bpt with camber") \
  X(qbz5, "ALIGNING_COEFFICIENTS", "QBZ5", 0.0, "Variation of slope Bpt with absolute camber") \
  X(qbz9, "ALIGNING_COEFFICIENTS", "QBZ9", 10.0, "Factor for scaling factors of slope factor Br of Mzr") \
  X(qbz10, "ALIGNING_COEFFICIENTS", "QBZ10", 0.0, "Factor for dimensionless cornering stiffness of Br of Mzr") \
  X(qcz1, "ALIGNING_COEFFICIENTS", "QCZ1", 1.1, "Shape factor Cpt for pneumatic trail") \
  X(qdz1, "ALIGNING_COEFFICIENTS", "QDZ1", 0.12, "Peak trail Dpt = Dpt*(Fz/Fznom*R0)") \
  X(qdz2, "ALIGNING_COEFFICIENTS", "QDZ2", 0.0, "Variation of peak Dpt'' with load") \
  X(qdz3, "ALIGNING_COEFFICIENTS", "QDZ3", 0.0, "Variation of peak Dpt'' with camber") \
  X(qdz4, "ALIGNING_COEFFICIENTS", "QDZ4", 0.0, "Variation of peak Dpt'' with camber squared") \
  X(qdz6, "ALIGNING_COEFFICIENTS", "QDZ6", 0.0, "Peak residual torque Dmr'' = Dmr/(Fz*R0)") \
  X(qdz7, "ALIGNING_COEFFICIENTS", "QDZ7", 0.0, "Variation of peak factor Dmr'' with load") \
  X(qdz8, "ALIGNING_COEFFICIENTS", "QDZ8", -0.05, "Variation of peak factor Dmr'' with camber") \
  X(qdz9, "ALIGNING_COEFFICIENTS", "QDZ9", 0.0, "Variation of peak factor Dmr'' with camber and load") \
  X(qdz10, "ALIGNING_COEFFICIENTS", "QDZ10", 0.0, "Variation of peak factor Dmr with camber squared") \
  X(qdz11, "ALIGNING_COEFFICIENTS", "QDZ11", 0.0, "Variation of Dmr with camber squared and load") \
  X(qez1, "ALIGNING_COEFFICIENTS", "QEZ1", 0.0, "Trail curvature Ept at Fznom") \
  X(qez2, "ALIGNING_COEFFICIENTS", "QEZ2", 0.0, "Variation of curvature Ept with load") \
  X(qez3, "ALIGNING_COEFFICIENTS", "QEZ3", 0.0, "Variation of curvature Ept with load squared") \
  X(qez4, "ALIGNING_COEFFICIENTS", "QEZ4", 0.0, "Variation of curvature Ept with sign of Alpha-t") \
  X(qez5, "ALIGNING_COEFFICIENTS", "QEZ5", 0.0, "Variation of Ept with camber and sign Alpha-t") \
  X(qhz1, "ALIGNING_COEFFICIENTS", "QHZ1", 0.0, "Trail horizontal shift Sht at Fznom") \
  X(qhz2, "ALIGNING_COEFFICIENTS", "QHZ2", 0.0, "Variation of shift Sht with load") \
  X(qhz3, "ALIGNING_COEFFICIENTS", "QHZ3", 0.0, "Variation of shift Sht with camber") \
  X(qhz4, "ALIGNING_COEFFICIENTS", "QHZ4", 0.0, "Variation of shift Sht with camber and load") \
  X(ppz1, "ALIGNING_COEFFICIENTS", "PPZ1", 0.0, "effect of inflation pressure on length of pneumatic trail") \
  X(ppz2, "ALIGNING_COEFFICIENTS", "PPZ2", 0.0, "Influence of inflation pressure on residual aligning torque") \
  X(ssz1, "ALIGNING_COEFFICIENTS", "SSZ1", 0.0, "Nominal value of s/R0: effect of Fx on Mz") \
  X(ssz2, "ALIGNING_COEFFICIENTS", "SSZ2", 0.0, "Variation of distance s/R0 with Fy/Fznom") \
  X(ssz3, "ALIGNING_COEFFICIENTS", "SSZ3", 0.0, "Variation of distance s/R0 with camber") \
  X(ssz4, "ALIGNING_COEFFICIENTS", "SSZ4", 0.0, "Variation of distance s/R0 with load and camber") \
  /* [TURNSLIP_COEFFICIENTS] */ \
  X(pdxp1, "TURNSLIP_COEFFICIENTS", "PDXP1", 0.4, "Peak Fx reduction due to spin parameter") \
  X(pdxp2, "TURNSLIP_COEFFICIENTS", "PDXP2", 0.0, "Peak Fx reduction due to spin with varying load parameter") \
  X(pdxp3, "TURNSLIP_COEFFICIENTS", "PDXP3", 0.0, "Peak Fx reduction due to spin with kappa parameter") \
  X(pkyp1, "TURNSLIP_COEFFICIENTS", "PKYP1", 1.0, "Cornering stiffness reduction due to spin") \
  X(pdyp1, "TURNSLIP_COEFFICIENTS", "PDYP1", 0.4, "Peak Fy reduction due to spin parameter") \
  X(pdyp2, "TURNSLIP_COEFFICIENTS", "PDYP2", 0.0, "Peak Fy reduction due to spin with varying load parameter") \
  X(pdyp3, "TURNSLIP_COEFFICIENTS", "PDYP3", 0.0, "Peak Fy reduction due to spin with alpha parameter") \
  X(pdyp4, "TURNSLIP_COEFFICIENTS", "PDYP4", 0.0, "Peak Fy reduction due to square root of spin parameter") \
  X(phyp1, "TURNSLIP_COEFFICIENTS", "PHYP1", 1.0, "Fy-alpha curve lateral shift limitation") \
  X(phyp2, "TURNSLIP_COEFFICIENTS", "PHYP2", 0.15, "Fy-alpha curve maximum lateral shift parameter") \
  X(phyp3, "TURNSLIP_COEFFICIENTS", "PHYP3", 0.0, "Fy-alpha curve maximum lateral shift varying with load parameter") \
  X(phyp4, "TURNSLIP_COEFFICIENTS", "PHYP4", -4.0, "Fy-alpha curve maximum lateral shift parameter") \
  X(pecp1, "TURNSLIP_COEFFICIENTS", "PECP1", 0.5, "Camber w.r.t. spin reduction factor parameter in camber stiffness") \
  X(pecp2, "TURNSLIP_COEFFICIENTS", "PECP2", 0.0, "Camber w.r.t. spin reduction factor varying with load parameter in camber stiffness") \
  X(qdtp1, "TURNSLIP_COEFFICIENTS", "QDTP1", 10.0, "Pneumatic trail reduction factor due to turn slip parameter") \
  X(qcrp1, "TURNSLIP_COEFFICIENTS", "QCRP1", 0.2, "Turning moment at constant turning and zero forward speed parameter") \
  X(qcrp2, "TURNSLIP_COEFFICIENTS", "QCRP2", 0.1, "Turn slip moment (at alpha = 90deg) parameter for increase with spin") \
  X(qbrp1, "TURNSLIP_COEFFICIENTS", "QBRP1", 0.1, "Residual (spin) torque reduction factor parameter due to side slip") \
  X(qdrp1, "TURNSLIP_COEFFICIENTS", "QDRP1", 1.0, "Turn slip moment peak magnitude parameter") \
  /* end */
// clang-format on

/// FITTYP: which equation set. PAC2002 (Adams) shares the MF 5.2 equations in steady state.
enum class FitType : std::uint8_t {
  mf52 = 6,  ///< MF-Tyre 5.2 (FITTYP 6, also 21), as MFeval evaluates it
  /// Adams PAC2002 (a file without FITTYP) in steady state (ζ = 1): the MF 5.2 equations with the
  /// camber scale factors γx = γ·LGAX (Fx), γy = γ·LGAY (Fy), γz = γ·LGAZ (Mz), which MFeval's
  /// MF 5.2 path ignores. Same code path as mf52.
  pac2002 = 2,
  mf61 = 61,  ///< MF 6.1 (FITTYP 61)
  mf62 = 62,  ///< MF 6.2 (FITTYP 62)
};

/// TYRESIDE of the property file: the side the coefficients describe.
enum class TyreSide : std::uint8_t { left, right };

template <typename T>
struct MfParameters {
  FitType fit_type = FitType::mf61;
  TyreSide tyre_side = TyreSide::left;
#define TREAD_MF_DECLARE_MEMBER(member, section, key, value, description) T member = T(value);
  TREAD_MF_PARAMETER_LIST(TREAD_MF_DECLARE_MEMBER)
#undef TREAD_MF_DECLARE_MEMBER
};

/// Whether the parameters take the MF 5.2 equations: FITTYP 6 (MF-Tyre 5.2) and PAC2002, which
/// shares them in steady state.
template <typename T>
constexpr bool is_mf5x(const MfParameters<T>& p) {
  return p.fit_type == FitType::mf52 || p.fit_type == FitType::pac2002;
}

/// The number of coefficients in TREAD_MF_PARAMETER_LIST.
inline constexpr int kMfParameterCount = 0
#define TREAD_MF_COUNT_MEMBER(member, section, key, value, description) +1
    TREAD_MF_PARAMETER_LIST(TREAD_MF_COUNT_MEMBER)
#undef TREAD_MF_COUNT_MEMBER
    ;

/// The same parameters in another scalar: float for the ECU, ceres::Jet for the fitter. `U` must
/// be constructible from a double (explicit constructors are fine).
template <typename U>
constexpr MfParameters<U> convert_parameters(const MfParameters<double>& p) {
  MfParameters<U> out;
  out.fit_type = p.fit_type;
  out.tyre_side = p.tyre_side;
#define TREAD_MF_CONVERT_MEMBER(member, section, key, value, description) out.member = U(p.member);
  TREAD_MF_PARAMETER_LIST(TREAD_MF_CONVERT_MEMBER)
#undef TREAD_MF_CONVERT_MEMBER
  return out;
}

}  // namespace tread::mf
