!> Abaqus/Standard parallel-execution information for user code ("Obtaining parallel processes information" in
!> the Abaqus User Subroutines Guide): CALL GETNUMCPUS(NUMPROCESSES), CALL GETRANK(RANK), and the INTEGER functions
!> GETNUMTHREADS(), GET_THREAD_ID() and GETCOMMUNICATOR(). The processes are those the host registered with
!> abaqus_set_processes (an MPI run: its ranks and MPI_COMM_WORLD; otherwise one process of rank 0 and communicator
!> 0, which Abaqus documents for a run without MPI); the threads are the element loop's (OpenMP, -t N), the calling
!> thread's number 0 outside the loop. GETVRM (material
!> point data for USDFLD) has nothing to return here: a call stops the run with a message naming it.

!> GETNUMCPUS: number of processes of the analysis.
subroutine getnumcpus(numprocesses)
  use abaqus_host_state, only: abaqus_processes
  implicit none
  integer, intent(out) :: numprocesses  !< number of MPI processes
  integer :: rank, comm
  call abaqus_processes(rank, numprocesses, comm)
end subroutine getnumcpus

!> GETRANK: rank of the calling process.
subroutine getrank(rank)
  use abaqus_host_state, only: abaqus_processes
  implicit none
  integer, intent(out) :: rank  !< MPI rank
  integer :: count, comm
  call abaqus_processes(rank, count, comm)
end subroutine getrank

!> GETNUMTHREADS: number of threads running the element loop.
integer function getnumthreads()
  !$ use omp_lib, only: omp_get_max_threads, omp_get_num_threads, omp_in_parallel
  implicit none
  getnumthreads = 1
  !$ if (omp_in_parallel()) then
  !$   getnumthreads = omp_get_num_threads()
  !$ else
  !$   getnumthreads = omp_get_max_threads()
  !$ end if
end function getnumthreads

!> GET_THREAD_ID: number of the calling thread, 0 for the first (and outside the element loop).
integer function get_thread_id()
  !$ use omp_lib, only: omp_get_thread_num
  implicit none
  get_thread_id = 0
  !$ get_thread_id = omp_get_thread_num()
end function get_thread_id

!> GETCOMMUNICATOR: MPI communicator of the analysis; 0 in a run without MPI.
integer function getcommunicator()
  use abaqus_host_state, only: abaqus_processes
  implicit none
  integer :: rank, count
  call abaqus_processes(rank, count, getcommunicator)
end function getcommunicator

!> GETVRM is not provided: end the run with a message that names it (rather than reading memory that is not there).
subroutine getvrm(var, array, jarray, flgray, jrcd, jmac, jmatyp, matlayo, laccfla)
  use, intrinsic :: iso_fortran_env, only: error_unit
  implicit none
  character(len=*), intent(in) :: var  !< requested output variable key
  double precision :: array(*)         !< not set
  integer :: jarray(*)                 !< not set
  character(len=*) :: flgray(*)        !< not set
  integer :: jrcd                      !< not set
  integer :: jmac(*), jmatyp(*), matlayo, laccfla  !< not read
  write (error_unit, '(a)') 'ldfcz: ***ERROR: GETVRM('''//trim(var)//''') is not provided by ldfcz: it serves '// &
    'USDFLD, which the host does not call; UMAT and UEL receive their state in their arguments. The analysis stops.'
  flush (error_unit)
  error stop 3
end subroutine getvrm
