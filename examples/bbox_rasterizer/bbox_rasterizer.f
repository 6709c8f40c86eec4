// The example rasterizer (bbox_rasterizer.sv): rastersim cosim --dut examples/bbox_rasterizer/bbox_rasterizer.f
// --top bbox_rasterizer --compare triangle
bbox_rasterizer.sv
