!     ldfcz: Abaqus/Standard UEL of the LDF cohesive element
!     (van den Bosch, Schreurs, Geers 2007, sections 4-5). Thin adapter:
!     checks sizes and properties, unpacks, calls the pure core
!     (module cohesive_element), packs RHS, AMATRX, SVARS, ENERGY.
!
!     Element (chosen from NNODE and MCRD, never from JTYPE):
!       NNODE = 8, MCRD >= 3, NDOFEL = 24: 3D, nodes 1-4 bottom face,
!         5-8 top face, node k+4 on node k, counter-clockwise seen
!         from the top (as COH3D8); 2x2 Gauss points.
!       NNODE = 4, MCRD >= 2, NDOFEL = 8: plane strain, per unit
!         thickness, ordered as COH2D4 (1-2 bottom, 3-4 top, node 3
!         on node 2, node 4 on node 1); 2 Gauss points.
!     PROPS(1) phi (N/mm) > 0, PROPS(2) delta (mm) > 0,
!     PROPS(3) k_c (MPa) >= 0, 0 or absent: k_c = phi/delta,
!     PROPS(4) phi_t, PROPS(5) delta_t (classical law only; 0 or
!       absent: phi, delta).
!     PROPS(6) eta_v >= 0 (N s/mm^3), optional viscous regularisation
!       T += eta_v dDelta/DTIME (0 or absent: none, the paper's law);
!       its dissipation is added to ENERGY(4).
!     PROPS(7) (2D only) out-of-plane thickness of a plane-strain or
!       plane-stress section (0 or absent: 1, per unit thickness);
!       Abaqus passes a user element no *SOLID SECTION data.
!     JPROPS(3) (2D only) 1: axisymmetric about x2 (x1 = r, as CAX4),
!       each point weighted by 2 pi R (R of the initial mid-line):
!       forces, AMATRX and energies are totals over 2 pi radians
!       like the CAX elements'; 0 or absent: planar.
!     JPROPS(1) unloading 1 reversible, 2 elastic damage, 3 plastic
!       (0 or absent: 1). JPROPS(2) law 1 LDF, 2 classical (0 or
!       absent: 1); the classical law is reversible only.
!     SVARS: 4 per Gauss point, point-major: Delta_max, |Delta|, |T|,
!       Delta_c = Delta.n; NSVARS >= 16 (3D) or 8 (2D).
!     RHS(:,1) = -f_int, AMATRX = -dRHS/dU (unsymmetric in contact:
!       declare UNSYMM), ENERGY(2) recoverable, ENERGY(4) dissipated.
!     LFLAGS(3): 1 RHS and AMATRX, 2 AMATRX, 5 RHS, 3 and 4 (damping,
!       mass) AMATRX = 0, 6 AMATRX = 0 (mass) and RHS.
!     PNEWDT is written (0.25) only when U is not finite or the
!     current mid-surface is degenerate; accuracy control is the
!     host's. Reentrant: no SAVE, no COMMON.
      SUBROUTINE UEL(RHS,AMATRX,SVARS,ENERGY,NDOFEL,NRHS,NSVARS,
     1 PROPS,NPROPS,COORDS,MCRD,NNODE,U,DU,V,A,JTYPE,TIME,DTIME,
     2 KSTEP,KINC,JELEM,PARAMS,NDLOAD,JDLTYP,ADLMAG,PREDEF,NPREDF,
     3 LFLAGS,MLVARX,DDLMAG,MDLOAD,PNEWDT,JPROPS,NJPROP,PERIOD)
      USE LDFCZ_FINITE, ONLY: IS_FINITE
      USE COHESIVE_LAW, ONLY: COHESIVE_PROPS
      USE COHESIVE_INPUT, ONLY: COHESIVE_SECTION, COHESIVE_INPUT_READ,
     1 INPUT_OK
      USE COHESIVE_ELEMENT, ONLY: COHESIVE_ELEMENT_COMPUTE,
     1 NSV_PER_IP, ELEMENT_NIP, STAT_OK, STAT_BAD_INPUT
      INCLUDE 'ABA_PARAM.INC'
      INTEGER NDOFEL, NRHS, NSVARS, NPROPS, MCRD, NNODE, JTYPE
      INTEGER KSTEP, KINC, JELEM, NDLOAD, NPREDF, MLVARX, MDLOAD
      INTEGER NJPROP, JDLTYP, LFLAGS, JPROPS
      DOUBLE PRECISION RHS, AMATRX, SVARS, ENERGY, PROPS, COORDS
      DOUBLE PRECISION U, DU, V, A, TIME, DTIME, PARAMS, ADLMAG
      DOUBLE PRECISION PREDEF, DDLMAG, PNEWDT, PERIOD
      DIMENSION RHS(MLVARX,*),AMATRX(NDOFEL,NDOFEL),PROPS(*),
     1 SVARS(*),ENERGY(8),COORDS(MCRD,NNODE),U(NDOFEL),
     2 DU(MLVARX,*),V(NDOFEL),A(NDOFEL),TIME(2),PARAMS(*),
     3 JDLTYP(MDLOAD,*),ADLMAG(MDLOAD,*),DDLMAG(MDLOAD,*),
     4 PREDEF(2,NPREDF,NNODE),LFLAGS(*),JPROPS(*)
!
      TYPE(COHESIVE_PROPS) PR
      TYPE(COHESIVE_SECTION) SEC
      INTEGER NDIM, NEED, ISTAT, LF
      INTEGER INTV(3)
      DOUBLE PRECISION REALV(2), ESTO, EDIS, EVIS, EDS0, THICK
      DOUBLE PRECISION UST(NDOFEL)
      DOUBLE PRECISION FINT(NDOFEL), AK(NDOFEL,NDOFEL)
      DOUBLE PRECISION HOLD(NSVARS), HNEW(NSVARS)
      CHARACTER*8 CHARV(1)
      CHARACTER*200 EMSG
      LOGICAL WANTK, WANTF, AXI
!
      INTV = 0
      REALV = 0.0D0
      CHARV(1) = ' '
      INTV(1) = JELEM
!     --- element kind from NNODE, MCRD, NDOFEL
      IF (NNODE .EQ. 8 .AND. MCRD .GE. 3 .AND. NDOFEL .EQ. 24) THEN
        NDIM = 3
      ELSE IF (NNODE .EQ. 4 .AND. MCRD .GE. 2 .AND. NDOFEL .EQ. 8)
     1   THEN
        NDIM = 2
      ELSE
        INTV(1) = NNODE
        INTV(2) = MCRD
        INTV(3) = NDOFEL
        CALL STDB_ABQERR(-3, 'UEL ldfcz: unsupported element NNODE'
     1   //'=%I MCRD=%I NDOFEL=%I; need NNODE=8, MCRD>=3, NDOFEL=24'
     2   //' (3D) or NNODE=4, MCRD>=2, NDOFEL=8 (plane strain)',
     3   INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
!     --- properties (module cohesive_input: the UEL layout, checked)
      CALL COHESIVE_INPUT_READ(NDIM, PROPS(1:NPROPS),
     1 JPROPS(1:NJPROP), PR, SEC, ISTAT, EMSG)
      IF (ISTAT .NE. INPUT_OK) THEN
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: '//TRIM(EMSG),
     1   INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
      THICK = SEC%THICKNESS
      AXI = SEC%AXISYMMETRIC
!     --- state variables
      NEED = NSV_PER_IP * ELEMENT_NIP(NDIM)
      IF (NSVARS .LT. NEED) THEN
        INTV(2) = NSVARS
        INTV(3) = NEED
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: NSVARS=%I too'
     1   //' small, VARIABLES must be >= %I', INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
!     --- requested output
      LF = LFLAGS(3)
      IF (LF .NE. 1 .AND. LF .NE. 2 .AND. LF .NE. 3 .AND. LF .NE. 4
     1   .AND. LF .NE. 5 .AND. LF .NE. 6) THEN
        INTV(2) = LF
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: LFLAGS(3)=%I'
     1   //' not supported (1, 2, 3, 4, 5, 6 are)', INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
      WANTF = (LF .EQ. 1 .OR. LF .EQ. 5 .OR. LF .EQ. 6)
      WANTK = (LF .EQ. 1 .OR. LF .EQ. 2)
      IF (LF .EQ. 3 .OR. LF .EQ. 4 .OR. LF .EQ. 6) THEN
!       no mass, no damping in a cohesive interface
        AMATRX(1:NDOFEL, 1:NDOFEL) = 0.0D0
      END IF
!     --- geometry and displacements
      IF (.NOT. ALL(IS_FINITE(COORDS(1:NDIM, 1:NNODE)))) THEN
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: COORDS not'
     1   //' finite', INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
      IF (.NOT. ALL(IS_FINITE(U(1:NDOFEL)))) THEN
        CALL STDB_ABQERR(-1, 'UEL ldfcz: element %I: U not finite,'
     1   //' cutback requested', INTV, REALV, CHARV)
        IF (WANTF) RHS(1:NDOFEL, 1) = 0.0D0
        IF (WANTK) AMATRX(1:NDOFEL, 1:NDOFEL) = 0.0D0
        PNEWDT = 0.25D0
        RETURN
      END IF
!     --- the core
      HOLD = SVARS(1:NSVARS)
      IF (PR%ETA_V .GT. 0.0D0) THEN
!       viscous: rate from DU/DTIME; ENERGY(4) accumulates the
!       viscous dissipation on top of the law's (ENERGY on entry =
!       start of the increment)
        UST = U(1:NDOFEL) - DU(1:NDOFEL, 1)
        CALL COHESIVE_ELEMENT_COMPUTE(NDIM, COORDS(1:NDIM, 1:NNODE),
     1    U(1:NDOFEL), PR, HOLD, WANTK, FINT, AK, HNEW, ESTO, EDIS,
     2    ISTAT, EMSG, U_START=UST, DTIME=DTIME, E_VISC=EVIS,
     3    E_DISS_START=EDS0, THICKNESS=THICK, AXISYMMETRIC=AXI)
        EDIS = ENERGY(4) + (EDIS - EDS0) + EVIS
      ELSE
        CALL COHESIVE_ELEMENT_COMPUTE(NDIM, COORDS(1:NDIM, 1:NNODE),
     1    U(1:NDOFEL), PR, HOLD, WANTK, FINT, AK, HNEW, ESTO, EDIS,
     2    ISTAT, EMSG, THICKNESS=THICK, AXISYMMETRIC=AXI)
      END IF
      IF (ISTAT .NE. STAT_OK) THEN
        IF (ISTAT .EQ. STAT_BAD_INPUT) THEN
          CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: '//TRIM(EMSG),
     1     INTV, REALV, CHARV)
          CALL XIT()
          RETURN
        END IF
        CALL STDB_ABQERR(-1, 'UEL ldfcz: element %I: '//TRIM(EMSG)//
     1   ', cutback requested', INTV, REALV, CHARV)
        IF (WANTF) RHS(1:NDOFEL, 1) = 0.0D0
        IF (WANTK) AMATRX(1:NDOFEL, 1:NDOFEL) = 0.0D0
        PNEWDT = 0.25D0
        RETURN
      END IF
!     --- pack: RHS = -f_int, AMATRX = df_int/dU
      IF (WANTF) RHS(1:NDOFEL, 1) = -FINT
      IF (WANTK) AMATRX(1:NDOFEL, 1:NDOFEL) = AK
      SVARS(1:NSVARS) = HNEW
      ENERGY(2) = ESTO
      ENERGY(4) = EDIS
      RETURN
      END
