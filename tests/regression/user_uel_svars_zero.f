C     A user UEL with the index slip of a published one (test deck_user_files, case 8): the spring bed of
C     user_uel_elastic.f, which then clears its state variables in a loop whose index starts one too low, writing
C     SVARS(0) (a published UEL does this with K = 0 before a loop over SVARS(K)). In Abaqus the write lands in
C     another element's state; ldfcz must stop, naming the element and SVARS(0).
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
C     the slip: K starts at 0
      K = 0
      DO I = 1, NSVARS
        SVARS(K) = 0.0D0
        K = K + 1
      END DO
      RETURN
      END
