//! The engine of `geocert solve` and `geocert verify`: the input is read as a stream
//! ([`geocert::io::stream`]), each case is parsed and solved on a rayon pool of
//! `--jobs` threads, and a writer puts the results back in input order.
//!
//! - Output is in input order and byte-identical whatever `--jobs` (each result
//!   depends on its case only; `micros` is left out unless `--timings`).
//! - Cases go to the pool in batches of consecutive cases, sized from the measured
//!   time per case so that a batch is about [`BATCH_NANOS`] of work: one case at a
//!   time when cases are slow, up to [`MAX_BATCH`] when they are fast. A batch never
//!   waits more than [`BATCH_WAIT`] for cases that have not arrived: input that comes
//!   slowly (a pipe held open) is answered case by case as it comes.
//! - Memory stays flat: at most [`MAX_BATCH`] cases wait between the reading thread
//!   and the batcher, and at most [`WINDOW`] batches between the batcher and the
//!   writer (read, being solved, or solved and waiting for an earlier one).
//! - A result is written as soon as its batch and all before it are done; standard
//!   output is flushed whenever the writer would wait, so a run stopped by a timeout
//!   or Ctrl-C keeps every answer it had written (only a signal that lands in the
//!   middle of a write can leave the last line cut short).
//! - A panic while solving a case (a bug) becomes that case's `error` record of kind
//!   `internal`; the other cases go on.

use super::exit::{self, Status};
use super::output::{Context, Done};
use super::progress::Progress;
use geocert::io::stream::{CaseStream, Chunk};
use std::io::{BufRead, BufReader, Write};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, SyncSender, TryRecvError};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Batches in flight at most (read but not yet written).
pub const WINDOW: usize = 64;

/// Cases per batch at most: fast cases are handed to the pool in batches, so that
/// the hand-over between threads costs little per case.
const MAX_BATCH: usize = 256;

/// The work one batch should take: slow cases go one by one (for load balance), fast
/// ones up to [`MAX_BATCH`] at a time.
const BATCH_NANOS: u64 = 2_000_000;

/// The input, its size in bytes when known (for the progress bar).
type Input = (Box<dyn BufRead + Send>, Option<u64>);

fn open(file: &str) -> std::io::Result<Input> {
    if file == "-" {
        let stdin = BufReader::with_capacity(1 << 16, std::io::stdin());
        return Ok((Box::new(stdin), None));
    }
    let f = std::fs::File::open(file)?;
    let meta = f.metadata()?;
    if meta.is_dir() {
        return Err(std::io::Error::other("is a directory"));
    }
    let len = meta.is_file().then_some(meta.len());
    Ok((Box::new(BufReader::with_capacity(1 << 16, f)), len))
}

/// Run `ctx.mode` on every case of `file` (`-`: standard input); the exit status.
pub fn run(file: &str, ctx: Context, jobs: Option<usize>, progress: bool) -> Status {
    let command = ctx.mode.name();
    let mut status = Status::default();
    let (input, len) = match open(file) {
        Ok(x) => x,
        Err(e) => {
            eprintln!("geocert {command}: cannot read {file}: {e}");
            status.set(exit::UNREADABLE);
            return status;
        }
    };
    let threads = jobs.unwrap_or(0);
    let pool = match rayon::ThreadPoolBuilder::new().num_threads(threads).build() {
        Ok(pool) => pool,
        Err(e) => {
            eprintln!("geocert {command}: cannot start {threads} threads: {e}");
            status.set(exit::INTERNAL);
            return status;
        }
    };
    let progress = Progress::new(progress, len, command);
    let ctx = Arc::new(ctx);
    let stop = AtomicBool::new(false);
    let (done_tx, done_rx) = mpsc::channel::<Done>();
    let (slot_tx, slot_rx) = mpsc::sync_channel::<()>(WINDOW);
    let read_error = std::thread::scope(|s| {
        let writer = s.spawn(|| write_in_order(done_rx, slot_rx, &ctx, &progress, &stop));
        let read_error = feed(input, &pool, &ctx, done_tx, slot_tx, &stop);
        let report = writer.join().unwrap_or_else(|_| WriterReport {
            status: Status(exit::INTERNAL),
            ..WriterReport::default()
        });
        status.set(report.status.0);
        if let Some(e) = report.write_error {
            eprintln!("geocert {command}: cannot write to standard output: {e}");
        }
        read_error
    });
    progress.finish();
    if let Some(e) = read_error {
        eprintln!("geocert {command}: cannot read {file} to its end: {e}");
        status.set(exit::UNREADABLE);
    }
    report_counts(command, status);
    status
}

fn report_counts(command: &str, status: Status) {
    if status.has(exit::INTERNAL) {
        eprintln!(
            "geocert {command}: internal error in some case (a bug; see the `internal` records)"
        );
    }
    if status.has(exit::BAD_CASE) {
        eprintln!("geocert {command}: some case(s) could not be read or solved (`error` records)");
    }
    if status.has(exit::DISPUTED) {
        eprintln!("geocert {command}: some claim(s) refuted, undecided or missing a solution");
    }
}

/// How long a batch waits for more cases once it has one: input that arrives slowly
/// (a pipe held open, an interactive session) is solved without waiting for more.
const BATCH_WAIT: Duration = Duration::from_millis(1);

/// What the reader thread hands to the batcher: a case, or the end of the input (with
/// the read error that ended it, if any).
enum Read {
    Chunk(Chunk),
    End(Option<std::io::Error>),
}

/// Read chunks on a thread of their own, so that the batcher can tell "no case ready
/// now" from "no case yet": a bounded channel keeps memory flat. The thread is not
/// joined: when the run stops early (a write error) it may be blocked on standard
/// input, and it ends with the process.
fn spawn_reader(input: Box<dyn BufRead + Send>) -> Receiver<Read> {
    let (tx, rx) = mpsc::sync_channel::<Read>(MAX_BATCH);
    std::thread::spawn(move || {
        let mut stream = CaseStream::new(input);
        loop {
            let read = match stream.next_chunk() {
                Ok(Some(chunk)) => Read::Chunk(chunk),
                Ok(None) => Read::End(None),
                Err(e) => Read::End(Some(e)),
            };
            let end = matches!(read, Read::End(_));
            if tx.send(read).is_err() || end {
                break;
            }
        }
    });
    rx
}

/// The next batch: up to `size` chunks, waiting for the first as long as it takes and
/// for the others at most [`BATCH_WAIT`] after the first; `ended` is set at the end of
/// the input.
fn next_batch(
    chunks: &Receiver<Read>,
    size: usize,
    ended: &mut Option<Option<std::io::Error>>,
) -> Vec<Chunk> {
    let mut batch: Vec<Chunk> = Vec::with_capacity(size);
    let mut deadline: Option<Instant> = None;
    while batch.len() < size {
        let read = match deadline {
            None => chunks.recv().ok(),
            Some(deadline) => match chunks.try_recv() {
                Ok(read) => Some(read),
                Err(TryRecvError::Disconnected) => None,
                Err(TryRecvError::Empty) => {
                    match chunks.recv_timeout(deadline.saturating_duration_since(Instant::now())) {
                        Ok(read) => Some(read),
                        Err(RecvTimeoutError::Timeout) => return batch,
                        Err(RecvTimeoutError::Disconnected) => None,
                    }
                }
            },
        };
        match read {
            Some(Read::Chunk(chunk)) => {
                batch.push(chunk);
                deadline.get_or_insert_with(|| Instant::now() + BATCH_WAIT);
            }
            Some(Read::End(e)) => {
                *ended = Some(e);
                break;
            }
            // The reader went away without a word (it panicked): end of input.
            None => {
                *ended = Some(None);
                break;
            }
        }
    }
    batch
}

/// Read the cases and hand them to the pool in batches; the read error that ended
/// the input.
fn feed(
    input: Box<dyn BufRead + Send>,
    pool: &rayon::ThreadPool,
    ctx: &Arc<Context>,
    done_tx: mpsc::Sender<Done>,
    slot_tx: SyncSender<()>,
    stop: &AtomicBool,
) -> Option<std::io::Error> {
    let chunks = spawn_reader(input);
    // The measured time per case (nanoseconds, a running average over batches).
    let per_case = Arc::new(AtomicU64::new(BATCH_NANOS));
    let mut index = 0u64;
    let mut ended = None;
    while ended.is_none() && !stop.load(Ordering::Relaxed) {
        let size =
            (BATCH_NANOS / per_case.load(Ordering::Relaxed).max(1)).clamp(1, MAX_BATCH as u64);
        let batch = next_batch(&chunks, size as usize, &mut ended);
        if batch.is_empty() {
            break;
        }
        // Wait for a place in the window (the writer frees one per batch written).
        if slot_tx.send(()).is_err() {
            break;
        }
        let (ctx, tx, per_case) = (Arc::clone(ctx), done_tx.clone(), Arc::clone(&per_case));
        pool.spawn(move || {
            let start = Instant::now();
            let done = ctx.process_batch(index, batch);
            let nanos = start.elapsed().as_nanos() as u64 / done.cases.max(1);
            let old = per_case.load(Ordering::Relaxed);
            per_case.store((3 * old + nanos) / 4, Ordering::Relaxed);
            // The writer only goes away after every sender is dropped.
            let _ = tx.send(done);
        });
        index += 1;
    }
    ended.flatten()
}

#[derive(Default)]
struct WriterReport {
    status: Status,
    write_error: Option<std::io::Error>,
}

/// Standard output, and the first error writing to it (then nothing more is written).
struct Sink<'a> {
    out: std::io::BufWriter<std::io::StdoutLock<'static>>,
    report: WriterReport,
    stop: &'a AtomicBool,
}

impl Sink<'_> {
    fn result(&mut self, r: std::io::Result<()>) {
        if let Err(e) = r {
            self.report.status.set(exit::WRITE_FAILED);
            self.report.write_error = Some(e);
            self.stop.store(true, Ordering::Relaxed);
        }
    }
    fn write(&mut self, bytes: &[u8]) {
        if self.report.write_error.is_none() {
            let r = self.out.write_all(bytes);
            self.result(r);
        }
    }
    fn flush(&mut self) {
        if self.report.write_error.is_none() {
            let r = self.out.flush();
            self.result(r);
        }
    }
}

/// Write results in input order as they come; flush whenever nothing is ready.
fn write_in_order(
    done_rx: Receiver<Done>,
    slot_rx: Receiver<()>,
    ctx: &Context,
    progress: &Progress,
    stop: &AtomicBool,
) -> WriterReport {
    let mut sink = Sink {
        out: std::io::BufWriter::with_capacity(1 << 16, std::io::stdout().lock()),
        report: WriterReport::default(),
        stop,
    };
    if let Some(header) = ctx.header() {
        sink.write(header.as_bytes());
    }
    let mut ring: Vec<Option<Done>> = (0..WINDOW).map(|_| None).collect();
    let mut next = 0u64;
    let (mut cases, mut errors) = (0u64, 0u64);
    loop {
        let done = match done_rx.try_recv() {
            Ok(done) => done,
            Err(TryRecvError::Disconnected) => break,
            Err(TryRecvError::Empty) => {
                sink.flush();
                progress.update(cases, errors);
                match done_rx.recv_timeout(Duration::from_millis(200)) {
                    Ok(done) => done,
                    Err(RecvTimeoutError::Timeout) => continue,
                    Err(RecvTimeoutError::Disconnected) => break,
                }
            }
        };
        let slot = (done.index % WINDOW as u64) as usize;
        ring[slot] = Some(done);
        while let Some(done) = ring[(next % WINDOW as u64) as usize].take() {
            sink.write(done.text.as_bytes());
            sink.report.status.set(done.status.0);
            cases += done.cases;
            errors += done.errors;
            progress.advance(done.end);
            next += 1;
            // Free the place in the window.
            let _ = slot_rx.try_recv();
        }
    }
    sink.flush();
    progress.update(cases, errors);
    sink.report
}
