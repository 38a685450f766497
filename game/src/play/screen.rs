//! The window and its GPU surface: a winit window and a pixels buffer of the
//! internal frame size, which pixels scales to the window. The game hands it
//! finished `Framebuffer`s; this is the only place the frame leaves the CPU.

use std::sync::Arc;

use anyhow::{anyhow, Context, Result};
use pixels::wgpu::{Backends, TextureFormat};
use pixels::{Pixels, PixelsBuilder, ScalingMode, SurfaceTexture};
use sightline::Framebuffer;
use winit::dpi::PhysicalSize;
use winit::event_loop::ActiveEventLoop;
use winit::window::{CursorGrabMode, Fullscreen, Window};

/// How much of the screen the first window may cover.
const SCREEN_SHARE: f64 = 0.9;

#[derive(Clone)]
pub struct ScreenOptions {
    pub title: String,
    /// Internal frame size.
    pub frame: (u32, u32),
    /// Window inner size; `None` picks a whole multiple of the frame that fits.
    pub window: Option<(u32, u32)>,
    pub vsync: bool,
    /// Start full screen (borderless).
    pub fullscreen: bool,
}

pub struct Screen {
    pub window: Arc<Window>,
    pixels: Pixels<'static>,
    frame: (u32, u32),
}

impl Screen {
    pub fn open(event_loop: &ActiveEventLoop, options: &ScreenOptions) -> Result<Screen> {
        let (w, h) = options.window.unwrap_or_else(|| default_window_size(event_loop, options.frame));
        let attributes = Window::default_attributes()
            .with_title(&options.title)
            .with_inner_size(PhysicalSize::new(w, h))
            .with_min_inner_size(PhysicalSize::new(64, 40))
            .with_fullscreen(options.fullscreen.then_some(Fullscreen::Borderless(None)));
        let window = Arc::new(event_loop.create_window(attributes).context("cannot open a window")?);
        let size = window.inner_size();
        let mut failures = Vec::new();
        let mut pixels = None;
        for (name, backends) in backend_choices() {
            match surface_on(&window, options, backends) {
                Ok(p) => {
                    if !failures.is_empty() {
                        println!("window: presenting with {name}");
                    }
                    pixels = Some(p);
                    break;
                }
                Err(e) => failures.push(format!("{name}: {e}")),
            }
        }
        let Some(mut pixels) = pixels else { return Err(no_surface(&failures)) };
        pixels.set_scaling_mode(scaling_mode(options.frame, (size.width, size.height)));
        let mut screen = Screen { window, pixels, frame: options.frame };
        screen.resize(size.width, size.height)?;
        Ok(screen)
    }

    /// Follows the window's new inner size (physical pixels). A zero size
    /// (minimised) is ignored.
    pub fn resize(&mut self, width: u32, height: u32) -> Result<()> {
        if width == 0 || height == 0 {
            return Ok(());
        }
        self.pixels.set_scaling_mode(scaling_mode(self.frame, (width, height)));
        self.pixels.resize_surface(width, height).map_err(|e| anyhow!("cannot resize the window surface: {e}"))
    }

    /// Uploads `fb` (the internal size) and presents it; with vsync this
    /// waits for the display.
    pub fn present(&mut self, fb: &Framebuffer) -> Result<()> {
        // Framebuffer pixels hold RGBA bytes in memory order, as pixels'
        // Rgba8UnormSrgb texture does.
        for (dst, src) in self.pixels.frame_mut().chunks_exact_mut(4).zip(&fb.pixels) {
            dst.copy_from_slice(&src.to_ne_bytes());
        }
        self.pixels.render().map_err(|e| anyhow!("cannot present the frame: {e}"))
    }

    /// Whether the window is full screen now.
    pub fn fullscreen(&self) -> bool {
        self.window.fullscreen().is_some()
    }

    pub fn toggle_fullscreen(&self) {
        let next = match self.window.fullscreen() {
            Some(_) => None,
            None => Some(Fullscreen::Borderless(None)),
        };
        self.window.set_fullscreen(next);
    }

    /// Grabs (hides and holds) or releases the cursor; returns whether it is
    /// grabbed. Locked keeps raw motion coming without the pointer moving
    /// (Wayland, macOS); X11 offers only Confined, which is enough since
    /// turning reads raw device motion, not the pointer position.
    pub fn grab_cursor(&self, grab: bool) -> bool {
        if grab {
            let grabbed = self
                .window
                .set_cursor_grab(CursorGrabMode::Locked)
                .or_else(|_| self.window.set_cursor_grab(CursorGrabMode::Confined))
                .is_ok();
            self.window.set_cursor_visible(!grabbed);
            grabbed
        } else {
            let _ = self.window.set_cursor_grab(CursorGrabMode::None);
            self.window.set_cursor_visible(true);
            false
        }
    }
}

/// A pixels buffer of `frame` pixels on `window`. With `surface` (a plain,
/// non-sRGB 8-bit format) the frame's bytes go through untouched: they are
/// sRGB-encoded colours already, and an sRGB texture and surface would only
/// decode them to linear and encode them back, per pixel, per frame. That
/// round trip costs a software rasterizer dearly (lavapipe under Xvfb,
/// median upload+present per frame: 3.1 -> 2.5 ms at 640x400, roughly
/// 40-47 -> 30-42 ms at 1920x1080; see ARCHITECTURE.md). The one visible difference:
/// non-integer scaling blends neighbouring pixels in sRGB rather than linear
/// space, as Doom's own scalers did.
fn build_pixels(
    window: &Arc<Window>,
    frame: (u32, u32),
    vsync: bool,
    backends: Backends,
    surface: Option<TextureFormat>,
) -> Result<Pixels<'static>, pixels::Error> {
    let size = window.inner_size();
    // pixels panics on a zero-sized surface; a window can report one before
    // it is mapped.
    let texture = SurfaceTexture::new(size.width.max(1), size.height.max(1), Arc::clone(window));
    // Vulkan, Metal, DirectX 12 first (see `backend_choices`); OpenGL only
    // when they fail: pixels 0.17 on Mesa's software GL was found not to
    // present (and on a machine without Mesa's EGL finds no adapter at
    // all), whereas software Vulkan (lavapipe) works under Xvfb.
    let builder = PixelsBuilder::new(frame.0, frame.1, texture).wgpu_backend(backends).enable_vsync(vsync);
    match surface {
        Some(format) => builder.texture_format(TextureFormat::Rgba8Unorm).surface_texture_format(format).build(),
        None => builder.build(),
    }
}

/// The backends to try, in order: the one `WGPU_BACKEND` names (if set),
/// then Vulkan, Metal or DirectX 12, then OpenGL.
fn backend_choices() -> Vec<(String, Backends)> {
    let mut choices = Vec::new();
    if let Some(named) = Backends::from_env().filter(|b| !b.is_empty()) {
        let var = std::env::var("WGPU_BACKEND").unwrap_or_default();
        choices.push((format!("WGPU_BACKEND={var}"), named));
    }
    for (name, backends) in [("Vulkan, Metal or DirectX 12", Backends::PRIMARY), ("OpenGL", Backends::GL)] {
        if choices.iter().all(|(_, b)| *b != backends) {
            choices.push((name.to_string(), backends));
        }
    }
    choices
}

/// The window's surface on `backends`, or why not: an error, or a panic
/// inside the graphics stack turned into one (wgpu panics on some
/// adapters, e.g. "Surface does not support the adapter's queue family";
/// no panic of it reaches the player).
fn surface_on(window: &Arc<Window>, options: &ScreenOptions, backends: Backends) -> Result<Pixels<'static>, String> {
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let made = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| plain_surface(window, options, backends)));
    std::panic::set_hook(hook);
    match made {
        Ok(made) => made.map_err(|e| {
            let detail = std::error::Error::source(&e).map(|s| format!(" ({s})")).unwrap_or_default();
            format!("{e}{detail}")
        }),
        Err(panic) => {
            let what = panic
                .downcast_ref::<String>()
                .map(String::as_str)
                .or_else(|| panic.downcast_ref::<&str>().copied())
                .unwrap_or("a panic");
            Err(format!("the graphics stack failed: {what}"))
        }
    }
}

/// pixels' default, an sRGB surface, exists everywhere; with it in hand
/// the surface's formats are known, and a plain 8-bit one replaces it
/// (see `build_pixels`). The second set-up costs about 60 ms once.
fn plain_surface(
    window: &Arc<Window>,
    options: &ScreenOptions,
    backends: Backends,
) -> Result<Pixels<'static>, pixels::Error> {
    let build = |format| build_pixels(window, options.frame, options.vsync, backends, format);
    let pixels = build(None)?;
    let plain = pixels
        .context()
        .surface_capabilities
        .formats
        .iter()
        .copied()
        .find(|f| matches!(f, TextureFormat::Bgra8Unorm | TextureFormat::Rgba8Unorm));
    match plain {
        Some(format) => {
            // One swapchain per window at a time (Vulkan refuses a second).
            drop(pixels);
            build(Some(format))
        }
        None => Ok(pixels),
    }
}

/// Crisp nearest-neighbour scaling when a whole multiple of the frame fills
/// the window in one direction (the other is letterboxed either way);
/// otherwise fill the window keeping the aspect ratio, filtered linearly.
fn scaling_mode(frame: (u32, u32), window: (u32, u32)) -> ScalingMode {
    let k = (window.0 / frame.0).min(window.1 / frame.1);
    if k >= 1 && (k * frame.0 == window.0 || k * frame.1 == window.1) {
        ScalingMode::PixelPerfect
    } else {
        ScalingMode::Fill
    }
}

/// The frame times the largest whole factor that fits in 90% of the screen,
/// at least 1.
fn default_window_size(event_loop: &ActiveEventLoop, frame: (u32, u32)) -> (u32, u32) {
    let monitor = event_loop.primary_monitor().or_else(|| event_loop.available_monitors().next());
    let k = monitor.map_or(1.0, |m| {
        let size = m.size();
        (f64::from(size.width) * SCREEN_SHARE / f64::from(frame.0))
            .min(f64::from(size.height) * SCREEN_SHARE / f64::from(frame.1))
            .floor()
    });
    let k = (k.max(1.0) as u32).min(8);
    (frame.0 * k, frame.1 * k)
}

/// No backend could present: each one's failure, and what to install.
/// (Without a Vulkan driver, or without the Vulkan loader, wgpu has no
/// instance to make a surface with, so that shows as a surface error, not
/// a missing adapter.)
fn no_surface(failures: &[String]) -> anyhow::Error {
    anyhow!(
        "no graphics backend could present the window:\n  {}\n\
         On Debian or Ubuntu, Mesa's software Vulkan driver provides one:\n    \
         sudo apt-get install mesa-vulkan-drivers libvulkan1\n\
         Headless frames need no GPU: sightline capture MAP -o frame.png",
        failures.join("\n  ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crisp_only_at_whole_multiples() {
        assert!(matches!(scaling_mode((640, 400), (640, 400)), ScalingMode::PixelPerfect));
        assert!(matches!(scaling_mode((640, 400), (1280, 1000)), ScalingMode::PixelPerfect));
        assert!(matches!(scaling_mode((640, 400), (1920, 1080)), ScalingMode::Fill));
        assert!(matches!(scaling_mode((640, 400), (300, 200)), ScalingMode::Fill));
    }
}
