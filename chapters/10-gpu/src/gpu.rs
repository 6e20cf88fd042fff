//! The GPU: finding one, compiling the tracer for it, and one frame —
//! upload, dispatch, readback, in bands of rows when the image is too big
//! for one buffer.
//!
//! On a machine without a graphics card, Mesa's lavapipe is a Vulkan
//! "GPU" that runs the shader on the CPU's cores (compiled by LLVM, eight
//! lanes of AVX2 per core); wgpu's default choice of adapter picks it.

use std::time::{Duration, Instant};

use raylab::{Camera, Scene, Settings};
use wgpu::util::DeviceExt;

use crate::scene_buffer::{Inputs, PENDING_SIZE, PROGRESS_SIZE};
use crate::shader::{self, ShaderError, Source};

/// Set (to anything) to make the program find no adapter, as on a
/// machine without Vulkan: how the tests check that message.
pub const NO_ADAPTER_VAR: &str = "RAYLAB_NO_GPU";

/// Invocations per workgroup side: `@workgroup_size(8, 8)` in tracer.wgsl.
pub const TILE: u32 = 8;

/// Six counters per image row: five ray kinds and the samples cut short.
const COUNTERS_PER_ROW: u64 = 6;

/// The most bytes of ray stacks kept between dispatches: a band's rows
/// are as many as fit (one row at least). More rows per band would mean
/// fewer, bigger dispatches, but every new buffer is cleared first.
const STACK_BYTES: u64 = 32 << 20;

/// Why the GPU could not render; each is one line.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum GpuError {
    #[error(
        "no GPU adapter found ({0}): chapter 10 needs Vulkan; on Debian or Ubuntu, \
         `apt-get install mesa-vulkan-drivers` gives lavapipe, which runs it on the CPU"
    )]
    NoAdapter(String),
    #[error("the GPU adapter refused a device: {0}")]
    Device(String),
    #[error(
        "one row of a {width}-pixel-wide image needs {bytes} bytes, more than this GPU's \
         buffers hold ({limit}): make the image narrower"
    )]
    TooBig { width: u32, bytes: u64, limit: u64 },
    #[error("the GPU failed: {0}")]
    Failed(String),
}

/// The tracer compiled for the GPU: a compute pipeline, ready to dispatch.
pub struct Pipeline {
    pub pipeline: wgpu::ComputePipeline,
    /// The shader's name in messages: `tracer.wgsl`, or the `--shader` file.
    pub name: String,
    /// The deepest ray its stack has room for.
    pub max_depth: u32,
    /// How long naga and the driver took to make it.
    pub compile_time: Duration,
}

/// One frame's results, read back from the GPU.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// Per pixel, row by row from the top: the linear colour.
    pub pixels: Vec<[f32; 3]>,
    /// Per pixel: the deepest ray and the number of rays traced.
    pub maps: Vec<[u32; 2]>,
    /// Rays traced, by kind, in the order of `RayKind::ALL`.
    pub counts: [u64; 5],
    /// Samples whose ray tree reached the ray budget.
    pub over_budget: u64,
    /// Uploading the inputs, running the shader, and waiting for it.
    pub dispatch: Duration,
    /// How many times the shader ran over a band until all its pixels
    /// were done, summed over the bands.
    pub dispatches: u32,
    /// Copying the results to memory the CPU can read, and reading them.
    pub readback: Duration,
}

/// An adapter, its device and queue, and the tracer's binding layout.
pub struct Gpu {
    device: wgpu::Device,
    queue: wgpu::Queue,
    layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    /// The adapter's name and driver, for the summary line.
    pub adapter: String,
}

/// A storage buffer in the layout, read-only or not.
fn storage(binding: u32, read_only: bool) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

impl Gpu {
    /// The GPU for a test that needs one: where there is none it says so
    /// and gives `None` (the test then checks nothing), unless `CI` is
    /// set, where a missing adapter is a failure (CI installs lavapipe).
    /// Shared by the tests of every crate that renders on the GPU.
    pub fn for_tests() -> Option<Gpu> {
        match Gpu::new() {
            Ok(gpu) => Some(gpu),
            Err(error) if std::env::var_os("CI").is_none() => {
                eprintln!(
                    "this test needs a GPU adapter and found none, so it checked nothing: {error}"
                );
                None
            }
            Err(error) => panic!("this test needs a GPU adapter (CI installs lavapipe): {error}"),
        }
    }

    /// The default adapter (lavapipe on a machine without a GPU).
    pub fn new() -> Result<Gpu, GpuError> {
        if std::env::var_os(NO_ADAPTER_VAR).is_some() {
            return Err(GpuError::NoAdapter(format!("{NO_ADAPTER_VAR} is set")));
        }
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: wgpu::Backends::VULKAN,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let adapter =
            pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
                .map_err(|e| GpuError::NoAdapter(e.to_string()))?;
        let info = adapter.get_info();
        let adapter_name = if info.driver_info.is_empty() {
            info.name.clone()
        } else {
            format!("{} ({})", info.name, info.driver_info)
        };
        // Ask for all the adapter has: big images need big storage buffers.
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("ch10-gpu"),
            required_limits: adapter.limits(),
            ..Default::default()
        }))
        .map_err(|e| GpuError::Device(e.to_string()))?;

        let uniform = wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("tracer inputs and outputs"),
            entries: &[
                uniform,
                storage(1, true),
                storage(2, true),
                storage(3, false),
                storage(4, false),
                storage(5, false),
                storage(6, false),
                storage(7, false),
                storage(8, false),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("tracer"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        Ok(Gpu {
            device,
            queue,
            layout,
            pipeline_layout,
            adapter: adapter_name,
        })
    }

    /// Check the shader with naga (a mistake is one line with its place),
    /// then compile it for this GPU with its ray stack sized for
    /// `max_depth`.
    pub fn compile(&self, source: &Source, max_depth: u32) -> Result<Pipeline, ShaderError> {
        let start = Instant::now();
        let source = &source.with_stack_size(max_depth);
        shader::check(source)?;
        // A shader can be valid WGSL and still not fit the program: a
        // binding of the wrong type, no `main`. wgpu reports those to an
        // error scope instead of panicking.
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = self
            .device
            .create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(&source.name),
                source: wgpu::ShaderSource::Wgsl(source.text.as_str().into()),
            });
        let pipeline = self
            .device
            .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(&source.name),
                layout: Some(&self.pipeline_layout),
                module: &module,
                entry_point: Some("main"),
                compilation_options: Default::default(),
                cache: None,
            });
        if let Some(error) = pollster::block_on(scope.pop()) {
            return Err(ShaderError::Whole {
                file: source.name.clone(),
                message: one_line(&error.to_string()),
            });
        }
        let tracer = Pipeline {
            pipeline,
            name: source.name.clone(),
            max_depth,
            compile_time: Duration::ZERO,
        };
        // A driver may compile the shader only when it first runs
        // (lavapipe does, with LLVM): one pixel makes that part of the
        // compile time, not of the first frame's.
        let pixel = Settings {
            width: 1,
            height: 1,
            max_depth,
            epsilon: 1e-4,
            sampling: raylab::Sampling::PIXEL_CENTRE,
        };
        let features = crate::Like::AntiAliasing.features();
        let inputs = crate::scene_buffer::pack(&Scene::lab(), &Camera::lab(), &pixel, features)
            .expect("one ray through the pixel centre packs");
        self.render(&tracer, &inputs)
            .map_err(|error| ShaderError::Whole {
                file: source.name.clone(),
                message: error.to_string(),
            })?;
        Ok(Pipeline {
            compile_time: start.elapsed(),
            ..tracer
        })
    }

    /// Render one frame: upload `inputs`, run one invocation per pixel,
    /// read the colours, maps and counts back. An image too big for one
    /// storage buffer goes in bands of rows, one dispatch each.
    pub fn render(&self, tracer: &Pipeline, inputs: &Inputs) -> Result<Frame, GpuError> {
        let limits = self.device.limits();
        let limit = limits
            .max_storage_buffer_binding_size
            .min(limits.max_buffer_size);
        // The biggest buffer per pixel is its ray stack.
        let stack_bytes = stack_bytes(tracer.max_depth);
        let row_bytes = u64::from(inputs.width) * stack_bytes.max(16);
        if row_bytes > limit {
            return Err(GpuError::TooBig {
                width: inputs.width,
                bytes: row_bytes,
                limit,
            });
        }
        let rows = (limit.min(STACK_BYTES) / row_bytes)
            .max(1)
            .min(u64::from(inputs.height));
        self.render_in_bands(tracer, inputs, u32::try_from(rows).unwrap_or(u32::MAX))
    }

    /// [`Gpu::render`] in bands of at most `rows_per_band` rows.
    pub fn render_in_bands(
        &self,
        tracer: &Pipeline,
        inputs: &Inputs,
        rows_per_band: u32,
    ) -> Result<Frame, GpuError> {
        if inputs.max_depth > tracer.max_depth {
            return Err(GpuError::Failed(format!(
                "the tracer was compiled for a max depth of {}, not {}",
                tracer.max_depth, inputs.max_depth
            )));
        }
        let pixels = inputs.width as usize * inputs.height as usize;
        let mut frame = Frame {
            pixels: Vec::with_capacity(pixels),
            maps: Vec::with_capacity(pixels),
            counts: [0; 5],
            over_budget: 0,
            dispatch: Duration::ZERO,
            dispatches: 0,
            readback: Duration::ZERO,
        };
        let rows_per_band = rows_per_band.max(1).min(inputs.height);
        let start = Instant::now();
        let work = self.work_buffers(tracer, u64::from(inputs.width) * u64::from(rows_per_band));
        frame.dispatch += start.elapsed();
        let mut first_row = 0;
        while first_row < inputs.height {
            let rows = rows_per_band.min(inputs.height - first_row);
            let band = self.render_band(tracer, inputs, &work, first_row, rows)?;
            frame.pixels.extend(band.pixels);
            frame.maps.extend(band.maps);
            for (total, n) in frame.counts.iter_mut().zip(band.counts) {
                *total += n;
            }
            frame.over_budget += band.over_budget;
            frame.dispatch += band.dispatch;
            frame.dispatches += band.dispatches;
            frame.readback += band.readback;
            first_row += rows;
        }
        Ok(frame)
    }

    /// The buffers a band's pixels keep their work in between dispatches,
    /// for bands of up to `pixels` pixels: made once per frame.
    fn work_buffers(&self, tracer: &Pipeline, pixels: u64) -> WorkBuffers {
        let buffer = |label, size, usage| {
            self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size,
                usage: wgpu::BufferUsages::STORAGE | usage,
                mapped_at_creation: false,
            })
        };
        let copy_dst = wgpu::BufferUsages::COPY_DST;
        let copy_src = wgpu::BufferUsages::COPY_SRC;
        WorkBuffers {
            progress: buffer("progress", pixels * PROGRESS_SIZE as u64, copy_dst),
            stacks: buffer(
                "stacks",
                pixels * stack_bytes(tracer.max_depth),
                wgpu::BufferUsages::empty(),
            ),
            unfinished: buffer("unfinished", 4, copy_dst | copy_src),
            unfinished_read: self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("unfinished readback"),
                size: 4,
                usage: wgpu::BufferUsages::MAP_READ | copy_dst,
                mapped_at_creation: false,
            }),
        }
    }

    /// One band of `rows` rows from `first_row` down.
    fn render_band(
        &self,
        tracer: &Pipeline,
        inputs: &Inputs,
        work: &WorkBuffers,
        first_row: u32,
        rows: u32,
    ) -> Result<Frame, GpuError> {
        let start = Instant::now();
        let pixels = u64::from(inputs.width) * u64::from(rows);
        let colour_bytes = pixels * 16;
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let init = |label, contents: &[u8], usage| {
            self.device
                .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some(label),
                    contents,
                    usage,
                })
        };
        let params = init(
            "params",
            &inputs.band(first_row, rows),
            wgpu::BufferUsages::UNIFORM,
        );
        let spheres = init("spheres", &inputs.spheres, wgpu::BufferUsages::STORAGE);
        let samples = init("samples", &inputs.samples, wgpu::BufferUsages::STORAGE);
        let out = |label, size| {
            self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size,
                usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            })
        };
        // New buffers are zeroed, which the counters rely on.
        let outputs = [
            out("pixels", colour_bytes),
            out("maps", pixels * 8),
            out("counts", u64::from(inputs.height) * COUNTERS_PER_ROW * 4),
        ];
        let bind_group = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("tracer"),
            layout: &self.layout,
            entries: &[
                (0, &params),
                (1, &spheres),
                (2, &samples),
                (3, &outputs[0]),
                (4, &outputs[1]),
                (5, &outputs[2]),
                (6, &work.progress),
                (7, &work.stacks),
                (8, &work.unfinished),
            ]
            .map(|(binding, buffer)| wgpu::BindGroupEntry {
                binding,
                resource: buffer.as_entire_binding(),
            }),
        });

        // ANCHOR: dispatch
        // Every pixel starts at its first sample.
        let mut encoder = self.device.create_command_encoder(&Default::default());
        encoder.clear_buffer(&work.progress, 0, None);
        let mut dispatches = 0;
        loop {
            encoder.clear_buffer(&work.unfinished, 0, None);
            {
                let mut pass = encoder.begin_compute_pass(&Default::default());
                pass.set_pipeline(&tracer.pipeline);
                pass.set_bind_group(0, &bind_group, &[]);
                pass.dispatch_workgroups(inputs.width.div_ceil(TILE), rows.div_ceil(TILE), 1);
            }
            encoder.copy_buffer_to_buffer(&work.unfinished, 0, &work.unfinished_read, 0, 4);
            self.queue.submit([encoder.finish()]);
            dispatches += 1;
            // Again, until no pixel is left unfinished.
            if self.read_u32(&work.unfinished_read)? == 0 {
                break;
            }
            encoder = self.device.create_command_encoder(&Default::default());
        }
        let dispatch = start.elapsed();
        // ANCHOR_END: dispatch

        let start = Instant::now();
        let mut encoder = self.device.create_command_encoder(&Default::default());
        let staging = outputs.each_ref().map(|buffer| {
            let copy = self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("readback"),
                size: buffer.size(),
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            encoder.copy_buffer_to_buffer(buffer, 0, &copy, 0, buffer.size());
            copy
        });
        self.queue.submit([encoder.finish()]);
        for buffer in &staging {
            buffer.map_async(wgpu::MapMode::Read, .., |_| {});
        }
        self.wait()?;
        if let Some(error) = pollster::block_on(scope.pop()) {
            return Err(GpuError::Failed(one_line(&error.to_string())));
        }
        let read = |buffer: &wgpu::Buffer| -> Result<Vec<u32>, GpuError> {
            let view = buffer
                .get_mapped_range(..)
                .map_err(|e| GpuError::Failed(e.to_string()))?;
            Ok(view
                .chunks_exact(4)
                .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
                .collect())
        };
        let colours = read(&staging[0])?;
        let maps = read(&staging[1])?;
        let rows = read(&staging[2])?;
        let mut counts = [0u64; 5];
        let mut over_budget = 0;
        for row in rows.chunks_exact(COUNTERS_PER_ROW as usize) {
            for (total, n) in counts.iter_mut().zip(row) {
                *total += u64::from(*n);
            }
            over_budget += u64::from(row[5]);
        }
        let frame = Frame {
            pixels: colours
                .chunks_exact(4)
                .map(|c| [c[0], c[1], c[2]].map(f32::from_bits))
                .collect(),
            maps: maps.chunks_exact(2).map(|m| [m[0], m[1]]).collect(),
            counts,
            over_budget,
            dispatch,
            dispatches,
            readback: start.elapsed(),
        };
        Ok(frame)
    }

    /// Wait for the GPU, then read the one number in `buffer`.
    fn read_u32(&self, buffer: &wgpu::Buffer) -> Result<u32, GpuError> {
        buffer.map_async(wgpu::MapMode::Read, .., |_| {});
        self.wait()?;
        let number = {
            let view = buffer
                .get_mapped_range(..)
                .map_err(|e| GpuError::Failed(e.to_string()))?;
            u32::from_le_bytes([view[0], view[1], view[2], view[3]])
        };
        buffer.unmap();
        Ok(number)
    }

    /// Block until the GPU has done all it was given.
    fn wait(&self) -> Result<(), GpuError> {
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map(|_| ())
            .map_err(|e| GpuError::Failed(e.to_string()))
    }
}

/// Where a band's pixels keep their work between dispatches.
struct WorkBuffers {
    progress: wgpu::Buffer,
    stacks: wgpu::Buffer,
    unfinished: wgpu::Buffer,
    unfinished_read: wgpu::Buffer,
}

/// The bytes of one pixel's ray stack, as `tracer.wgsl` sizes it.
fn stack_bytes(max_depth: u32) -> u64 {
    u64::from(max_depth) * PENDING_SIZE as u64
}

/// A message on one line: wgpu's errors run over several.
fn one_line(text: &str) -> String {
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join(" ")
}
