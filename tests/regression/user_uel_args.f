C     A fixed-form user UEL that records the arguments the host passes on every call (test deck_uel_arguments):
C     one line per call in <output directory>/uel_args.txt with KSTEP, KINC, JELEM, JTYPE, LFLAGS(1:5),
C     TIME(1:2), DTIME, PERIOD, PARAMS(1:3), NDLOAD, NRHS, MLVARX and the sum of |PROPS| and |JPROPS| over
C     the 16 entries after NPROPS and NJPROP (0: the host pads both with zeros), then behaves as the spring bed of
C     user_uel_elastic.f (stiffness PROPS(1) per unit area between node K and node K+4). Run with --threads 1.
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
      OPEN(NEWUNIT=IU, FILE=OUTDIR(1:LENOUT)//'/uel_args.txt',
     1 POSITION='APPEND', ACTION='WRITE')
      PAST = 0.0D0
      DO K = 1, 16
        PAST = PAST + ABS(PROPS(NPROPS + K)) + ABS(JPROPS(NJPROP + K))
      END DO
      WRITE(IU,'(9(I0,1X),7(ES23.15,1X),3(I0,1X),ES10.3)') KSTEP, KINC,
     1 JELEM, JTYPE, (LFLAGS(I), I = 1, 5), TIME(1), TIME(2), DTIME,
     2 PERIOD, PARAMS(1), PARAMS(2), PARAMS(3), NDLOAD, NRHS, MLVARX, PAST
      CLOSE(IU)
      SK = PROPS(1)/4.0D0
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
      RETURN
      END
