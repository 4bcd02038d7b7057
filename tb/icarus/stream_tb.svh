// The cycle loop every Icarus testbench of tb/icarus shares (included at the end of the
// testbench module): clock, reset, input items from a vector file, output transactions to a
// file, the valid/ready handshakes, deadlock and duplicate detection. It follows
// tb/harness/rtl_runner.hpp and handshake_driver.hpp: rst_ni low for 5 clock edges; then each
// cycle presents at most one item (valid and data held until the channel accepts it), samples
// both handshakes on settled values before the edge, and clocks; after the last expected
// output it clocks 16 more cycles with the output ready so that an extra output shows up.
//
// The including module declares clk_i, rst_ni, in_valid, in_ready, out_valid, out_ready, its
// DUT, and:
//   function automatic bit load_item(input integer fd);  // read one line of fields (hex)
//   task automatic clear_item;                           // data inputs when nothing is presented
//   task automatic write_output(input integer fd, input longint unsigned cycle);  // one line
//
// Plusargs: +in=FILE (one item per line, fields in hex) +items=N +out=FILE +expected=N
// [+seed=S] [+in_idle=P] [+out_stall=P] (per mille) [+max_idle=C].
// The output file gets one line per output transaction, "<cycle> <field> ..." (cycle decimal,
// fields hex), and at the end "# cycles <n>", or "# error <why>" when the run failed.

  integer fd_in, fd_out;
  integer seed = 1, in_idle = 0, out_stall = 0;
  longint unsigned items = 0, expected = 0, max_idle = 100000;
  longint unsigned cycle = 0, accepted = 0, outputs = 0, last_progress = 0;
  reg [8*4096-1:0] in_path, out_path;
  bit presenting = 0, in_fire, out_fire, failed = 0, running = 1;
  integer drain = 0;

  initial clk_i = 1'b0;
  always #5 clk_i = ~clk_i;

  // True with probability permille / 1000, from the testbench's seeded generator.
  function automatic bit coin(input integer permille);
    integer r;
    r = $random(seed);
    return permille > 0 && ($unsigned(r) % 1000) < permille;
  endfunction

  initial begin
    if (!$value$plusargs("in=%s", in_path) || !$value$plusargs("out=%s", out_path) ||
        !$value$plusargs("items=%d", items) || !$value$plusargs("expected=%d", expected)) begin
      $display("ERROR: usage: +in=FILE +items=N +out=FILE +expected=N");
      $finish;
    end
    if ($value$plusargs("seed=%d", seed)) begin end
    if ($value$plusargs("in_idle=%d", in_idle)) begin end
    if ($value$plusargs("out_stall=%d", out_stall)) begin end
    if ($value$plusargs("max_idle=%d", max_idle)) begin end
    fd_in  = $fopen(in_path, "r");
    fd_out = $fopen(out_path, "w");
    if (fd_in == 0 || fd_out == 0) begin
      $display("ERROR: cannot open the vector files");
      $finish;
    end

    rst_ni    = 1'b0;
    in_valid  = 1'b0;
    out_ready = 1'b0;
    clear_item();
    repeat (5) @(posedge clk_i);
    #1 rst_ni = 1'b1;

    while (running) begin
      // Drive this cycle's inputs (just after the previous edge).
      if (!presenting && accepted < items && !coin(in_idle)) begin
        if (!load_item(fd_in)) begin
          $fdisplay(fd_out, "# error item %0d: cannot read its fields", accepted);
          failed = 1;
        end
        presenting = !failed;
      end
      if (!presenting) clear_item();
      in_valid  = presenting;
      out_ready = !coin(out_stall);
      // Sample the handshakes on the settled values the edge will see.
      @(negedge clk_i);
      in_fire  = presenting && in_ready;
      out_fire = out_ready && out_valid;
      if (out_fire) begin
        write_output(fd_out, cycle);
        outputs++;
        last_progress = cycle;
      end
      if (in_fire) begin
        presenting = 0;
        accepted++;
        last_progress = cycle;
      end
      @(posedge clk_i);
      #1 cycle++;
      if (accepted == items && outputs >= expected) drain++;
      running = !failed && drain <= 16;
      if (running && cycle - last_progress > max_idle) begin
        $fdisplay(fd_out, "# error deadlock: no handshake for %0d cycles (cycle %0d, %0d of %0d items accepted, %0d of %0d outputs)",
                  max_idle, cycle, accepted, items, outputs, expected);
        failed  = 1;
        running = 0;
      end
    end
    if (!failed) $fdisplay(fd_out, "# cycles %0d", cycle);
    $fclose(fd_out);
    $fclose(fd_in);
    $finish;
  end
