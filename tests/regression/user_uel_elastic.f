C     A third-party style Abaqus UEL, written as users write them (fixed form, INCLUDE 'ABA_PARAM.INC',
C     implicit typing), to check that ldfcz --user compiles, loads and calls a user's own routine unchanged.
C
C     Linear elastic interface ("spring bed") of 8 nodes: nodes 1-4 the bottom face, 5-8 the top face
C     (node K+4 over node K). Every pair is joined by isotropic springs of stiffness PROPS(1) (N/mm^3, per unit
C     area) times a quarter of the bottom face's area, along each of the 3 displacement dofs.
C     RHS = -K U, AMATRX = K, ENERGY(2) = U.K.U/2. SVARS unused. Closed form: a uniform opening w gives the
C     total force PROPS(1) * w * A.
      SUBROUTINE UEL(RHS,AMATRX,SVARS,ENERGY,NDOFEL,NRHS,NSVARS,
     1 PROPS,NPROPS,COORDS,MCRD,NNODE,U,DU,V,A,JTYPE,TIME,DTIME,
     2 KSTEP,KINC,JELEM,PARAMS,NDLOAD,JDLTYP,ADLMAG,PREDEF,NPREDF,
     3 LFLAGS,MLVARX,DDLMAG,MDLOAD,PNEWDT,JPROPS,NJPROP,PERIOD)
      INCLUDE 'ABA_PARAM.INC'
      DIMENSION RHS(MLVARX,*),AMATRX(NDOFEL,NDOFEL),PROPS(*),
     1 SVARS(*),ENERGY(8),COORDS(MCRD,NNODE),U(NDOFEL),
     2 DU(MLVARX,*),V(NDOFEL),A(NDOFEL),TIME(2),PARAMS(*),
     3 JDLTYP(MDLOAD,*),ADLMAG(MDLOAD,*),DDLMAG(MDLOAD,*),
     4 PREDEF(2,NPREDF,NNODE),LFLAGS(*),JPROPS(*)
      DIMENSION D1(3),D2(3),CR(3)
C
      IF (NNODE.NE.8 .OR. NDOFEL.NE.24 .OR. NPROPS.LT.1) THEN
        WRITE(*,*) 'USER UEL: NEEDS 8 NODES, 24 DOFS, 1 PROPERTY'
        CALL XIT
        RETURN
      END IF
C     area of the bottom face from its diagonals
      DO I = 1, 3
        D1(I) = COORDS(I,3) - COORDS(I,1)
        D2(I) = COORDS(I,4) - COORDS(I,2)
      END DO
      CR(1) = D1(2)*D2(3) - D1(3)*D2(2)
      CR(2) = D1(3)*D2(1) - D1(1)*D2(3)
      CR(3) = D1(1)*D2(2) - D1(2)*D2(1)
      AREA = 0.5D0*SQRT(CR(1)**2 + CR(2)**2 + CR(3)**2)
      SK = PROPS(1)*AREA/4.0D0
C
      DO I = 1, NDOFEL
        RHS(I,1) = 0.0D0
        DO J = 1, NDOFEL
          AMATRX(I,J) = 0.0D0
        END DO
      END DO
      ENERGY(2) = 0.0D0
      DO K = 1, 4
        DO I = 1, 3
          IB = 3*(K-1) + I
          IT = 3*(K+3) + I
          AMATRX(IB,IB) = SK
          AMATRX(IT,IT) = SK
          AMATRX(IB,IT) = -SK
          AMATRX(IT,IB) = -SK
          F = SK*(U(IT) - U(IB))
          RHS(IB,1) = RHS(IB,1) + F
          RHS(IT,1) = RHS(IT,1) - F
          ENERGY(2) = ENERGY(2) + 0.5D0*F*(U(IT) - U(IB))
        END DO
      END DO
#ifdef LDFCZ_TEST_SVARS_SLIP
C     compiled with --fflags -DLDFCZ_TEST_SVARS_SLIP (test deck_user_files, case 8): the index slip of a published
C     UEL, a loop over SVARS whose index starts at 0, writing SVARS(0); ldfcz must stop, naming it
      K = 0
      DO I = 1, NSVARS
        SVARS(K) = 0.0D0
        K = K + 1
      END DO
#endif
      RETURN
      END
