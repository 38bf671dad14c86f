C     A user UMAT that uses Abaqus' thread utilities (test deck_user_files): the SMA arrays through
C     SMAAspUserSubroutines.hdr and Cray pointers, the mutexes, and the parallel-information routines.
C     Under mutex 7 it numbers its calls in a global integer array and writes each number to unit 6
C     (Abaqus: JOB.dat) with the calling thread and that thread's own call count, kept in a thread-local
C     array without a lock. The test reads JOB.dat: the global numbers must be exactly 1..N (the lock
C     works), each thread's counts 1..n_t with sum n_t = N (the thread-local arrays are private).
C     The stress is small-strain isotropic elasticity (ELASTIC_MATRIX, elastic_helper.f90).
C     UEXTERNALDB (below) records its calls.
      SUBROUTINE UMAT(STRESS,STATEV,DDSDDE,SSE,SPD,SCD,
     1 RPL,DDSDDT,DRPLDE,DRPLDT,
     2 STRAN,DSTRAN,TIME,DTIME,TEMP,DTEMP,PREDEF,DPRED,CMNAME,
     3 NDI,NSHR,NTENS,NSTATV,PROPS,NPROPS,COORDS,DROT,PNEWDT,
     4 CELENT,DFGRD0,DFGRD1,NOEL,NPT,LAYER,KSPT,JSTEP,KINC)
      include 'aba_param.inc'
#include <SMAAspUserSubroutines.hdr>
      CHARACTER*80 CMNAME
      DIMENSION STRESS(NTENS),STATEV(NSTATV),
     1 DDSDDE(NTENS,NTENS),DDSDDT(NTENS),DRPLDE(NTENS),
     2 STRAN(NTENS),DSTRAN(NTENS),TIME(2),PREDEF(1),DPRED(1),
     3 PROPS(NPROPS),COORDS(3),DROT(3,3),DFGRD0(3,3),DFGRD1(3,3),
     4 JSTEP(4)
      INTEGER GET_THREAD_ID, GETNUMTHREADS, GETCOMMUNICATOR
      INTEGER ICOUNT(1), LCOUNT(1), NCPU, MYRANK, ITHR, NTHR
      REAL*8 TOTAL(2)
      POINTER (PTRG, ICOUNT)
      POINTER (PTRL, LCOUNT)
      POINTER (PTRT, TOTAL)
#ifdef LDFCZ_TEST_BAD_MUTEX
C     compiled with --fflags -DLDFCZ_TEST_BAD_MUTEX: Abaqus has mutexes 1-100 only, the run must stop
      CALL MUTEXLOCK(101)
#endif
      ITHR = GET_THREAD_ID()
      NTHR = GETNUMTHREADS()
C     creation of the same global array by several threads returns the one array; mutex-protected here
C     only because the first creation and the first write must not interleave with a second thread's
      CALL MUTEXINIT(7)
      CALL MUTEXLOCK(7)
      PTRG = SMAIntArrayCreate(1, 1, 0)
      PTRT = SMAFloatArrayCreate(2, 2, 1.0D0)
      ICOUNT(1) = ICOUNT(1) + 1
      TOTAL(2) = TOTAL(2) + 1.0D0
      NCALL = ICOUNT(1)
      CALL MUTEXUNLOCK(7)
C     thread-local: created on a thread's first call (initial value 0), no lock
      IF (NCALL .EQ. 1 .OR. KINC .GE. 1) THEN
        PTRL = SMALocalIntArrayCreate(3, 1)
      END IF
      LCOUNT(1) = LCOUNT(1) + 1
      CALL MUTEXLOCK(7)
      WRITE(6,'(A,I8,A,I4,A,I8,A,I4,A,F12.1)') 'SMA_CALL ', NCALL,
     1 ' THREAD ', ITHR, ' LOCAL ', LCOUNT(1), ' NTHREADS ', NTHR,
     2 ' FLOAT ', TOTAL(2)
      CALL MUTEXUNLOCK(7)
      IF (NCALL .EQ. 1) THEN
        CALL GETNUMCPUS(NCPU)
        CALL GETRANK(MYRANK)
        WRITE(6,'(A,I4,A,I4,A,I4,A,I4)') 'SMA_INFO CPUS ', NCPU,
     1  ' RANK ', MYRANK, ' COMM ', GETCOMMUNICATOR(),
     2  ' SIZE ', SMAIntArraySize(1)
      END IF
      CALL ELASTIC_MATRIX(PROPS(1), PROPS(2), NDI, NTENS, DDSDDE)
      DO I = 1, NTENS
        DO J = 1, NTENS
          STRESS(I) = STRESS(I) + DDSDDE(I,J)*DSTRAN(J)
        END DO
      END DO
      RETURN
      END
C     UEXTERNALDB: initialises mutex 7 at the start of the analysis (as Abaqus' guide recommends) and records
C     every call in JOB.dat: LOP, LRESTART, KSTEP, KINC, TIME(1:2), DTIME.
      SUBROUTINE UEXTERNALDB(LOP,LRESTART,TIME,DTIME,KSTEP,KINC)
      INCLUDE 'ABA_PARAM.INC'
      DIMENSION TIME(2)
      IF (LOP .EQ. 0) CALL MUTEXINIT(7)
      WRITE(6,'(A,4(I6,1X),3(ES23.15,1X))') 'UEXT ', LOP, LRESTART,
     1 KSTEP, KINC, TIME(1), TIME(2), DTIME
      RETURN
      END
