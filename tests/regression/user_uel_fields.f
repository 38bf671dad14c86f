C     A fixed-form user element that records the predefined fields the host passes on every call (test
C     deck_fields): one line per call in <output directory>/uel_fields.txt with JELEM, KSTEP, KINC, NPREDF,
C     NNODE, TIME, DTIME and PREDEF(K1,K2,K3) for K1 = 1, 2 (value at the end of the increment, increment),
C     K2 = 1 .. NPREDF (temperature, then the field variables), K3 = 1 .. NNODE. The element is a spring of
C     stiffness PROPS(1) between its two nodes along each of the three dofs.
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
      CHARACTER*256 OUTDIR
      INTEGER LENOUT, IU
      CALL GETOUTDIR(OUTDIR, LENOUT)
      OPEN(NEWUNIT=IU, FILE=OUTDIR(1:LENOUT)//'/uel_fields.txt',
     1 POSITION='APPEND', ACTION='WRITE')
      WRITE(IU,'(5(I0,1X),100(ES24.16,1X))') JELEM, KSTEP, KINC,
     1 NPREDF, NNODE, TIME(1), TIME(2), DTIME,
     2 (((PREDEF(I,J,K), I = 1, 2), J = 1, NPREDF), K = 1, NNODE)
      CLOSE(IU)
      SK = PROPS(1)
      DO I = 1, NDOFEL
        DO J = 1, NDOFEL
          AMATRX(I,J) = 0.0D0
        END DO
      END DO
      DO I = 1, 3
        AMATRX(I,I) = SK
        AMATRX(I+3,I+3) = SK
        AMATRX(I,I+3) = -SK
        AMATRX(I+3,I) = -SK
      END DO
      DO I = 1, NDOFEL
        RHS(I,1) = 0.0D0
        DO J = 1, NDOFEL
          RHS(I,1) = RHS(I,1) - AMATRX(I,J)*U(J)
        END DO
      END DO
      RETURN
      END
