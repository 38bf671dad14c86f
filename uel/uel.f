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
      USE COHESIVE_LAW, ONLY: COHESIVE_PROPS, LAW_LDF, LAW_CLASSICAL
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
      INTEGER NDIM, NEED, IUNL, LAW, ISTAT, I, LF, ISEC
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
!     --- real properties
      IF (NPROPS .LT. 2) THEN
        INTV(2) = NPROPS
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: NPROPS=%I, need'
     1   //' at least 2 (PROPS(1)=phi, PROPS(2)=delta)',
     2   INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
      DO I = 1, MIN(NPROPS, 7)
        IF (.NOT. IS_FINITE(PROPS(I))) THEN
          INTV(2) = I
          CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: PROPS(%I) is'
     1     //' not a finite number (NaN or Inf)', INTV, REALV, CHARV)
          CALL XIT()
          RETURN
        END IF
      END DO
      IF (.NOT. (PROPS(1) .GT. 0.0D0)) THEN
        REALV(1) = PROPS(1)
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: PROPS(1) = phi'
     1   //' (work of separation) must be > 0, got %R',
     2   INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
      IF (.NOT. (PROPS(2) .GT. 0.0D0)) THEN
        REALV(1) = PROPS(2)
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: PROPS(2) = delta'
     1   //' (characteristic opening) must be > 0, got %R',
     2   INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
      DO I = 3, MIN(NPROPS, 7)
        IF (PROPS(I) .LT. 0.0D0) THEN
          INTV(2) = I
          REALV(1) = PROPS(I)
          CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: PROPS(%I)'
     1     //' (3 k_c, 4 phi_t, 5 delta_t, 6 eta_v, 7 thickness)'
     2     //' must be >= 0,'
     2     //' got %R',
     2     INTV, REALV, CHARV)
          CALL XIT()
          RETURN
        END IF
      END DO
      PR%PHI = PROPS(1)
      PR%DELTA = PROPS(2)
!     default k_c = phi/delta: T_c(Delta_c = -delta) = e*T_max
      PR%KC = PROPS(1) / PROPS(2)
      IF (NPROPS .GE. 3) THEN
        IF (PROPS(3) .GT. 0.0D0) PR%KC = PROPS(3)
      END IF
      PR%PHI_T = PROPS(1)
      IF (NPROPS .GE. 4) THEN
        IF (PROPS(4) .GT. 0.0D0) PR%PHI_T = PROPS(4)
      END IF
      PR%DELTA_T = PROPS(2)
      IF (NPROPS .GE. 5) THEN
        IF (PROPS(5) .GT. 0.0D0) PR%DELTA_T = PROPS(5)
      END IF
!     optional viscous regularisation eta_v (N s/mm^3); 0: none
      PR%ETA_V = 0.0D0
      IF (NPROPS .GE. 6) PR%ETA_V = PROPS(6)
!     --- integer properties
      IUNL = 1
      LAW = LAW_LDF
      IF (NJPROP .GE. 1) THEN
        IF (JPROPS(1) .NE. 0) IUNL = JPROPS(1)
      END IF
      IF (NJPROP .GE. 2) THEN
        IF (JPROPS(2) .NE. 0) LAW = JPROPS(2)
      END IF
      IF (IUNL .LT. 1 .OR. IUNL .GT. 3) THEN
        INTV(2) = IUNL
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: JPROPS(1) ='
     1   //' unloading type %I unknown; use 1 reversible, 2 elastic'
     2   //' damage, 3 plastic', INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
      IF (LAW .NE. LAW_LDF .AND. LAW .NE. LAW_CLASSICAL) THEN
        INTV(2) = LAW
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: JPROPS(2) = law'
     1   //' %I unknown; use 1 LDF, 2 classical', INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
      IF (LAW .EQ. LAW_CLASSICAL .AND. IUNL .NE. 1) THEN
        INTV(2) = IUNL
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: the classical'
     1   //' law (JPROPS(2)=2) is reversible only; JPROPS(1)=%I must'
     2   //' be 0 or 1', INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
      PR%UNLOADING = IUNL
      PR%LAW = LAW
!     --- section of the 2D element: thickness PROPS(7), JPROPS(3)
      THICK = 1.0D0
      IF (NPROPS .GE. 7) THEN
        IF (PROPS(7) .GT. 0.0D0) THICK = PROPS(7)
      END IF
      ISEC = 0
      IF (NJPROP .GE. 3) ISEC = JPROPS(3)
      IF (ISEC .NE. 0 .AND. ISEC .NE. 1) THEN
        INTV(2) = ISEC
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: JPROPS(3) ='
     1   //' %I unknown; use 0 planar (thickness PROPS(7)), 1'
     2   //' axisymmetric', INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
      IF (NDIM .EQ. 3 .AND. (ISEC .NE. 0 .OR. THICK .NE. 1.0D0)) THEN
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: PROPS(7)'
     1   //' (thickness) and JPROPS(3) (axisymmetric) apply to the'
     2   //' 2D element only; leave them 0 or absent in 3D',
     3   INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
      IF (ISEC .EQ. 1 .AND. THICK .NE. 1.0D0) THEN
        REALV(1) = THICK
        CALL STDB_ABQERR(-3, 'UEL ldfcz: element %I: axisymmetric'
     1   //' (JPROPS(3) = 1) takes no thickness, PROPS(7) = %R: the'
     2   //' forces are totals over 2 pi', INTV, REALV, CHARV)
        CALL XIT()
        RETURN
      END IF
      AXI = ISEC .EQ. 1
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
