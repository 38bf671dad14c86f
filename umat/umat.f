!     ldfcz: Abaqus/Standard UMAT of the compressible Leonov model
!     (van den Bosch, Schreurs, Geers 2007, section 6, Eqs. 31-42).
!     Thin adapter: checks sizes and properties, unpacks STATEV, calls
!     the pure core (module leonov), packs STRESS, STATEV, DDSDDE.
!
!     PROPS (NPROPS = 10, Table 1 order): E (MPa), nu, S_a, eta_0r
!       (MPa s), tau_0 (MPa), mu, G_r (MPa), r0, r1, r2; optional
!       PROPS(11) (NPROPS = 11): accuracy bound dgamma_max on the
!       plastic strain increment (default 0.05, see PNEWDT below).
!     STATEV (NSTATV >= 11, 12 in plane stress; all zero = virgin):
!       1-6  Be~ - I, order 11,22,33,12,13,23, spatial frame of the
!            current configuration (pushed forward with
!            F_rel = DFGRD1 DFGRD0^-1 here: the host need not rotate)
!       7    gamma_p, equivalent plastic strain
!       8    tau_bar (MPa), 9 eta (MPa s), 10 S = S_a R_gamma,
!       11   plastic rate dgamma_p/dt (1/s)   (8-11 outputs only)
!       12   plane stress only: ln(lambda_3), the thickness stretch
!     3D (NDI = 3, NSHR = 3, 11,22,33,12,13,23), plane strain or
!       axisymmetric (NDI = 3, NSHR = 1, 11,22,33,12) and plane
!       stress (NDI = 2, NSHR = 1, NTENS = 3, 11,22,12; NSTATV >= 12):
!       the UMAT finds the thickness stretch lambda_3 itself by a
!       local Newton iteration on sigma_33 = 0 (module
!       leonov_plane_stress), keeps ln(lambda_3) in STATEV(12) and
!       IGNORES DFGRD0(3,3), DFGRD1(3,3) and the out-of-plane entries
!       (Abaqus does not compute the thickness strain of a plane-
!       stress UMAT; see docs/umat.md); DDSDDE is the 3x3 tangent
!       condensed with d sigma_33 = 0.
!     Works from DFGRD0, DFGRD1 and DTIME; STRESS (input), STRAN,
!       DSTRAN, DROT are not used. STRESS = Cauchy stress.
!     DDSDDE: consistent tangent of the Jaumann rate of Kirchhoff
!       stress over J, analytic (implicit function theorem on the
!       return map, module leonov); not symmetric in general:
!       declare UNSYMM.
!     SSE, SPD per unit CURRENT volume (the host, like Abaqus for
!       the energy output (inferred), integrates them over the current
!       volume J dV): SSE = psi / J with, per unit reference volume,
!       psi = J (G/2 (tr Be~ - 3) + G_r/2 (tr B~ - 3)) + kappa/2 (J-1)^2
!       (the Cauchy deviators G dev Be~, G_r dev B~ of Eqs. 31-33 are
!       Kirchhoff deviators / J: J psi_dev; exact for J = 1, otherwise
!       short by int psi_dev dJ, ~3e-4 of the work in uniaxial tension
!       of PET: the model has no exact stored energy when J varies);
!       SPD = (SPD_n J_n + d) / J with d = (J_n tau_bar_n + J tau_bar)
!       dgamma_p / 2, the viscoplastic dissipation of the increment per
!       unit reference volume by the mid-point (trapezoidal) rule on
!       the dissipation rate J tau_bar gamma_p_dot (Eqs. 36-40):
!       second order in the increment like the host's trapezoidal
!       external work, so the energy balance is a consistency check
!       (docs/umat.md, tests/regression/check_energy_pet.py).
!       SCD unchanged.
!     PNEWDT (written only to request a cutback): 0.25 if the local
!       Newton fails or DFGRD1/STATEV are unusable (STRESS, STATEV
!       then unchanged, DDSDDE isotropic elastic); < 1 when
!       dgamma_p > dgamma_max in the increment. Reentrant: no SAVE
!       or COMMON.
      SUBROUTINE UMAT(STRESS,STATEV,DDSDDE,SSE,SPD,SCD,RPL,DDSDDT,
     1 DRPLDE,DRPLDT,STRAN,DSTRAN,TIME,DTIME,TEMP,DTEMP,PREDEF,DPRED,
     2 CMNAME,NDI,NSHR,NTENS,NSTATV,PROPS,NPROPS,COORDS,DROT,PNEWDT,
     3 CELENT,DFGRD0,DFGRD1,NOEL,NPT,LAYER,KSPT,JSTEP,KINC)
      USE LEONOV_PARAMETERS, ONLY: LEONOV_PROPS,
     1 LEONOV_PROPS_FROM_ARRAY, LEONOV_NPROPS, LEONOV_NPROPS_MAX,
     2 LEONOV_NSTATV
      USE LEONOV, ONLY: LEONOV_STATE, LEONOV_UPDATE,
     1 LEONOV_STATE_FROM_STATEV, LEONOV_STATE_TO_STATEV, LEONOV_OK,
     2 LEONOV_STEP_TOO_LARGE, LEONOV_ELASTIC_TANGENT
      USE LEONOV_PLANE_STRESS, ONLY: LEONOV_PLANE_STRESS_UPDATE
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*80 CMNAME
      INTEGER NDI, NSHR, NTENS, NSTATV, NPROPS, NOEL, NPT, LAYER
      INTEGER KSPT, JSTEP, KINC
      DOUBLE PRECISION STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL
      DOUBLE PRECISION DDSDDT, DRPLDE, DRPLDT, STRAN, DSTRAN, TIME
      DOUBLE PRECISION DTIME, TEMP, DTEMP, PREDEF, DPRED, PROPS
      DOUBLE PRECISION COORDS, DROT, PNEWDT, CELENT, DFGRD0, DFGRD1
      DIMENSION STRESS(NTENS),STATEV(NSTATV),DDSDDE(NTENS,NTENS),
     1 DDSDDT(NTENS),DRPLDE(NTENS),STRAN(NTENS),DSTRAN(NTENS),
     2 TIME(2),PREDEF(1),DPRED(1),PROPS(NPROPS),COORDS(3),DROT(3,3),
     3 DFGRD0(3,3),DFGRD1(3,3),JSTEP(4)
!
      TYPE(LEONOV_PROPS) PR
      TYPE(LEONOV_STATE) OLD, ANEW
      DOUBLE PRECISION SIG(3,3), C6(6,6), FACTOR, BT(3,3), DETF, DETF0
      DOUBLE PRECISION PSI, F0(3,3), F1(3,3), C3(3,3), XL3
      LOGICAL PSTRESS
      INTEGER ISTAT, K, L, INTV(1)
      INTEGER, PARAMETER :: IV(6) = [1, 2, 3, 1, 1, 2]
      INTEGER, PARAMETER :: JV(6) = [1, 2, 3, 2, 3, 3]
!     plane stress: components 11, 22, 12
      INTEGER, PARAMETER :: IP(3) = [1, 2, 1]
      INTEGER, PARAMETER :: JP(3) = [1, 2, 2]
      DOUBLE PRECISION REALV(1)
      CHARACTER(LEN=8) CHARV(1)
      CHARACTER(LEN=256) MSG
!
      INTV(1) = 0
      REALV(1) = 0.0D0
      CHARV(1) = ' '
      IF (NPROPS .LT. LEONOV_NPROPS) THEN
        WRITE (MSG, '(A,I0,A)') 'UMAT (Leonov): needs NPROPS = 10 '//
     1   '(E, nu, S_a, eta_0r, tau_0, mu, G_r, r0, r1, r2), got ',
     2   NPROPS, ' in *USER MATERIAL, CONSTANTS'
        GO TO 900
      END IF
      IF (NSTATV .LT. LEONOV_NSTATV) THEN
        WRITE (MSG, '(A,I0,A)') 'UMAT (Leonov): needs NSTATV >= 11 '//
     1   '(*DEPVAR), got ', NSTATV, ''
        GO TO 900
      END IF
      PSTRESS = NDI .EQ. 2 .AND. NSHR .EQ. 1 .AND. NTENS .EQ. 3
      IF (.NOT. PSTRESS .AND. (NDI .NE. 3 .OR. (NSHR .NE. 1 .AND.
     1 NSHR .NE. 3) .OR. NTENS .NE. NDI + NSHR)) THEN
        WRITE (MSG, '(A,I0,A,I0,A,I0)') 'UMAT (Leonov): supports NDI'
     1   //' = 3 with NSHR = 1 or 3 (3D, plane strain, axisymmetric)'
     2   //' and NDI = 2, NSHR = 1 (plane stress); got NDI = ', NDI,
     3   ', NSHR = ', NSHR, ', NTENS = ', NTENS
        GO TO 900
      END IF
      IF (PSTRESS .AND. NSTATV .LT. LEONOV_NSTATV + 1) THEN
        WRITE (MSG, '(A,I0,A)') 'UMAT (Leonov): plane stress needs '//
     1   'NSTATV >= 12 (*DEPVAR; STATEV(12) = ln of the thickness '//
     2   'stretch), got ', NSTATV, ''
        GO TO 900
      END IF
      CALL LEONOV_PROPS_FROM_ARRAY(PROPS(1:MIN(NPROPS,
     1 LEONOV_NPROPS_MAX)), PR, ISTAT, MSG)
      IF (ISTAT .NE. 0) THEN
        MSG = 'UMAT (Leonov): '//TRIM(MSG)
        GO TO 900
      END IF
!
      OLD = LEONOV_STATE_FROM_STATEV(STATEV(1:LEONOV_NSTATV))
      IF (PSTRESS) THEN
        CALL LEONOV_PLANE_STRESS_UPDATE(PR, DFGRD0, DFGRD1,
     1   STATEV(LEONOV_NSTATV + 1), DTIME, OLD, ANEW, SIG, XL3, ISTAT,
     2   FACTOR, C3, F0, F1)
      ELSE
        F0 = DFGRD0
        F1 = DFGRD1
        CALL LEONOV_UPDATE(PR, F0, F1, DTIME, OLD, ANEW, SIG,
     1   ISTAT, FACTOR, C6)
      END IF
      IF (ISTAT .NE. LEONOV_OK .AND. ISTAT .NE. LEONOV_STEP_TOO_LARGE)
     1 THEN
!       core failure: keep STRESS and STATEV, ask for a cutback
        C6 = LEONOV_ELASTIC_TANGENT(PR)
        DO L = 1, NTENS
          DO K = 1, NTENS
            IF (PSTRESS) THEN
              DDSDDE(K, L) = C3(K, L)
            ELSE
              DDSDDE(K, L) = C6(K, L)
            END IF
          END DO
        END DO
        PNEWDT = 0.25D0
        RETURN
      END IF
      DO K = 1, NTENS
        IF (PSTRESS) THEN
          STRESS(K) = SIG(IP(K), JP(K))
        ELSE
          STRESS(K) = SIG(IV(K), JV(K))
        END IF
        DO L = 1, NTENS
          IF (PSTRESS) THEN
            DDSDDE(K, L) = C3(K, L)
          ELSE
            DDSDDE(K, L) = C6(K, L)
          END IF
        END DO
        DDSDDT(K) = 0.0D0
        DRPLDE(K) = 0.0D0
      END DO
      CALL LEONOV_STATE_TO_STATEV(ANEW, STATEV(1:LEONOV_NSTATV))
      IF (PSTRESS) STATEV(LEONOV_NSTATV + 1) = XL3
!     energies per unit volume
      DETF = F1(1,1)*(F1(2,2)*F1(3,3)-F1(2,3)*F1(3,2))
     1 - F1(1,2)*(F1(2,1)*F1(3,3)-F1(2,3)*F1(3,1))
     2 + F1(1,3)*(F1(2,1)*F1(3,2)-F1(2,2)*F1(3,1))
      DETF0 = F0(1,1)*(F0(2,2)*F0(3,3)-F0(2,3)*F0(3,2))
     1 - F0(1,2)*(F0(2,1)*F0(3,3)-F0(2,3)*F0(3,1))
     2 + F0(1,3)*(F0(2,1)*F0(3,2)-F0(2,2)*F0(3,1))
      BT = MATMUL(F1, TRANSPOSE(F1)) * DETF**(-2.0D0/3.0D0)
      PSI = DETF*(0.5D0*PR%G*(ANEW%BE(1,1)+ANEW%BE(2,2)+ANEW%BE(3,3)
     1 -3.0D0) + 0.5D0*PR%G_R*(BT(1,1)+BT(2,2)+BT(3,3)-3.0D0))
     2 + 0.5D0*PR%KAPPA*(DETF-1.0D0)**2
      SSE = PSI / DETF
      SPD = (SPD*DETF0 + 0.5D0*(DETF0*OLD%TAU_BAR + DETF*ANEW%TAU_BAR)*
     1 ANEW%DGAMMA) / DETF
      IF (ISTAT .EQ. LEONOV_STEP_TOO_LARGE) THEN
        IF (.NOT. (PNEWDT .GT. 0.0D0 .AND. PNEWDT .LT. FACTOR))
     1   PNEWDT = FACTOR
      END IF
      RETURN
!
  900 CONTINUE
      CALL STDB_ABQERR(-3, TRIM(MSG), INTV, REALV, CHARV)
      CALL XIT()
      RETURN
      END SUBROUTINE UMAT
